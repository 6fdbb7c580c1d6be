#include "vk/buffer.h"

#include <utility>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

Buffer::Buffer(const Context &context, VkDeviceSize size, VkBufferUsageFlags usage,
               bool hostVisible, bool mappedWhereShared)
    : device_(context.device()), size_(size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer_));

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer_, &requirements);
    const VkMemoryPropertyFlags hostFlags =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkMemoryPropertyFlags wanted =
        hostVisible ? hostFlags : VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (!hostVisible && mappedWhereShared && context.sharesHostMemory() &&
        context.hasMemoryType(requirements.memoryTypeBits, wanted | hostFlags)) {
        wanted |= hostFlags;
        hostVisible = true;
    }
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = requirements.size;
    try {
        alloc.memoryTypeIndex = context.findMemoryType(requirements.memoryTypeBits, wanted);
        VK_CHECK(vkAllocateMemory(device_, &alloc, nullptr, &memory_));
        VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_, 0));
        if (hostVisible)
            VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
    } catch (...) {
        release();
        throw;
    }
}

Buffer::~Buffer() {
    release();
}

Buffer::Buffer(Buffer &&other) noexcept {
    *this = std::move(other);
}

Buffer &Buffer::operator=(Buffer &&other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

void Buffer::release() {
    if (buffer_)
        vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_)
        vkFreeMemory(device_, memory_, nullptr); // unmaps implicitly
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
}

} // namespace prism::vk
