#include "vk/descriptor_pool.h"

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

DescriptorPool::DescriptorPool(const Context &context,
                               const std::vector<VkDescriptorPoolSize> &sizes, uint32_t maxSets,
                               VkDescriptorPoolCreateFlags flags)
    : device_(context.device()) {
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.flags = flags;
    info.maxSets = maxSets;
    info.poolSizeCount = static_cast<uint32_t>(sizes.size());
    info.pPoolSizes = sizes.data();
    VK_CHECK(vkCreateDescriptorPool(device_, &info, nullptr, &pool_));
}

DescriptorPool::~DescriptorPool() {
    if (pool_)
        vkDestroyDescriptorPool(device_, pool_, nullptr);
}

} // namespace prism::vk
