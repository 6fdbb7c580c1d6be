#include "vk/buffer_view.h"

#include <utility>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

BufferView::BufferView(const Context &context, VkBuffer buffer, VkFormat format, VkDeviceSize range)
    : device_(context.device()) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer;
    info.format = format;
    info.offset = 0;
    info.range = range;
    VK_CHECK(vkCreateBufferView(device_, &info, nullptr, &view_));
}

BufferView::~BufferView() {
    release();
}

BufferView::BufferView(BufferView &&other) noexcept {
    *this = std::move(other);
}

BufferView &BufferView::operator=(BufferView &&other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    }
    return *this;
}

void BufferView::release() {
    if (view_)
        vkDestroyBufferView(device_, view_, nullptr);
    view_ = VK_NULL_HANDLE;
}

} // namespace prism::vk
