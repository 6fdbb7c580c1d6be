#include "vk/descriptor_set.h"

#include <map>

#include "vk/vk_check.h"

namespace prism::vk {

DescriptorSet::DescriptorSet(VkDevice device, std::vector<VkDescriptorType> types,
                             VkShaderStageFlags stages)
    : device_(device), types_(std::move(types)) {
    try {
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        std::map<VkDescriptorType, uint32_t> typeCounts;
        for (uint32_t i = 0; i < types_.size(); ++i) {
            bindings.push_back({i, types_[i], 1, stages, nullptr});
            typeCounts[types_[i]] += 1;
        }
        VkDescriptorSetLayoutCreateInfo setInfo{
            VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        setInfo.bindingCount = static_cast<uint32_t>(bindings.size());
        setInfo.pBindings = bindings.data();
        VK_CHECK(vkCreateDescriptorSetLayout(device_, &setInfo, nullptr, &layout_));

        std::vector<VkDescriptorPoolSize> sizes;
        for (auto [type, count] : typeCounts)
            sizes.push_back({type, count});
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.maxSets = 1;
        poolInfo.poolSizeCount = static_cast<uint32_t>(sizes.size());
        poolInfo.pPoolSizes = sizes.data();
        VK_CHECK(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_));

        VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        allocInfo.descriptorPool = pool_;
        allocInfo.descriptorSetCount = 1;
        allocInfo.pSetLayouts = &layout_;
        VK_CHECK(vkAllocateDescriptorSets(device_, &allocInfo, &set_));
    } catch (...) {
        destroy();
        throw;
    }
}

DescriptorSet::~DescriptorSet() {
    destroy();
}

void DescriptorSet::destroy() {
    if (pool_)
        vkDestroyDescriptorPool(device_, pool_, nullptr); // frees the set
    if (layout_)
        vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
    pool_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    set_ = VK_NULL_HANDLE;
}

VkWriteDescriptorSet DescriptorSet::writeFor(uint32_t binding) const {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = types_.at(binding);
    return write;
}

void DescriptorSet::writeBuffer(uint32_t binding, VkBuffer buffer, VkDeviceSize size) {
    VkDescriptorBufferInfo info{buffer, 0, size};
    VkWriteDescriptorSet write = writeFor(binding);
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void DescriptorSet::writeStorageImage(uint32_t binding, VkImageView view) {
    VkDescriptorImageInfo info{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet write = writeFor(binding);
    write.pImageInfo = &info;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void DescriptorSet::writeTexelBuffer(uint32_t binding, VkBufferView view) {
    VkWriteDescriptorSet write = writeFor(binding);
    write.pTexelBufferView = &view;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

SpecializationData::SpecializationData(const std::vector<SpecializationConstant> &constants) {
    for (const SpecializationConstant &c : constants) {
        entries.push_back({c.id, uint32_t(values.size()) * 4u, 4u});
        values.push_back(c.value);
    }
    info.mapEntryCount = static_cast<uint32_t>(entries.size());
    info.pMapEntries = entries.data();
    info.dataSize = values.size() * 4u;
    info.pData = values.data();
}

VkShaderModule createShaderModule(VkDevice device, const uint32_t *code, size_t bytes) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
    return module;
}

} // namespace prism::vk
