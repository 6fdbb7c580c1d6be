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
    Buffer(const Context &context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible);
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
