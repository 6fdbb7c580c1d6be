#include "vk/framebuffer.h"

#include <utility>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

Framebuffer::Framebuffer(const Context &context, VkRenderPass renderPass, VkImageView view,
                         VkExtent2D extent)
    : device_(context.device()) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VK_CHECK(vkCreateFramebuffer(device_, &info, nullptr, &framebuffer_));
}

Framebuffer::~Framebuffer() {
    release();
}

Framebuffer::Framebuffer(Framebuffer &&other) noexcept {
    *this = std::move(other);
}

Framebuffer &Framebuffer::operator=(Framebuffer &&other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        framebuffer_ = std::exchange(other.framebuffer_, VK_NULL_HANDLE);
    }
    return *this;
}

void Framebuffer::release() {
    if (framebuffer_)
        vkDestroyFramebuffer(device_, framebuffer_, nullptr);
    framebuffer_ = VK_NULL_HANDLE;
}

} // namespace prism::vk
