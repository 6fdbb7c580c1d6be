#pragma once
// A VkBuffer with its own memory. Move-only; the one owner that destroys both.
#include <cstddef>
#include <span>

#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class Buffer {
public:
    Buffer() = default;
    // hostVisible: mapped for the buffer's lifetime (readback and small per-frame data).
    // mappedWhereShared: device-local, and also mapped where the device shares the host's
    // memory and has a device-local type the host can write (Context::sharesHostMemory), so
    // the caller can fill it in place; mapped() says whether it is.
    Buffer(const Context &context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
           bool mappedWhereShared = false);
    ~Buffer();
    Buffer(Buffer &&other) noexcept;
    Buffer &operator=(Buffer &&other) noexcept;
    Buffer(const Buffer &) = delete;
    Buffer &operator=(const Buffer &) = delete;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void *mapped() const { return mapped_; }

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    void *mapped_ = nullptr;
};

} // namespace prism::vk
