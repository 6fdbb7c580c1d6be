#pragma once
// A VkDescriptorPool for code that allocates its own sets (the overlay's UI library).
// Move-only owner; destroying it frees every set allocated from it.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class DescriptorPool {
public:
    DescriptorPool(const Context &context, const std::vector<VkDescriptorPoolSize> &sizes,
                   uint32_t maxSets, VkDescriptorPoolCreateFlags flags = 0);
    ~DescriptorPool();
    DescriptorPool(const DescriptorPool &) = delete;
    DescriptorPool &operator=(const DescriptorPool &) = delete;

    VkDescriptorPool handle() const { return pool_; }

private:
    VkDevice device_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

} // namespace prism::vk
