#pragma once
// One descriptor set with its own set layout and pool, for a pipeline that needs exactly one
// (binding i has type types[i], one descriptor). The single owner of all three handles.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace prism::vk {

class DescriptorSet {
public:
    DescriptorSet(VkDevice device, std::vector<VkDescriptorType> types, VkShaderStageFlags stages);
    ~DescriptorSet();
    DescriptorSet(const DescriptorSet &) = delete;
    DescriptorSet &operator=(const DescriptorSet &) = delete;

    VkDescriptorSetLayout layout() const { return layout_; }
    const VkDescriptorSet &handle() const { return set_; }

    // The caller makes sure no command buffer in flight uses the set.
    void writeBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize size = VK_WHOLE_SIZE);
    void writeStorageImage(uint32_t binding, VkImageView view);
    void writeTexelBuffer(uint32_t binding, VkBufferView view);

private:
    VkWriteDescriptorSet writeFor(uint32_t binding) const;
    void destroy();
    VkDevice device_;
    std::vector<VkDescriptorType> types_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

// One 32-bit specialization constant: the shader's constant_id and its value.
struct SpecializationConstant {
    uint32_t id;
    uint32_t value;
};

// Keeps the values and map entries alive for as long as `info` is used.
struct SpecializationData {
    explicit SpecializationData(const std::vector<SpecializationConstant> &constants);
    std::vector<uint32_t> values;
    std::vector<VkSpecializationMapEntry> entries;
    VkSpecializationInfo info{};
    const VkSpecializationInfo *pointer() const { return values.empty() ? nullptr : &info; }
};

VkShaderModule createShaderModule(VkDevice device, const uint32_t *code, size_t bytes);

} // namespace prism::vk
