#pragma once
// A VkBufferView: a typed view of a buffer for uniform texel buffer bindings. Move-only; the
// one owner that destroys it (the buffer itself stays with its own owner).
#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class BufferView {
public:
    BufferView() = default;
    BufferView(const Context &context, VkBuffer buffer, VkFormat format,
               VkDeviceSize range = VK_WHOLE_SIZE);
    ~BufferView();
    BufferView(BufferView &&other) noexcept;
    BufferView &operator=(BufferView &&other) noexcept;
    BufferView(const BufferView &) = delete;
    BufferView &operator=(const BufferView &) = delete;

    VkBufferView handle() const { return view_; }

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkBufferView view_ = VK_NULL_HANDLE;
};

} // namespace prism::vk
