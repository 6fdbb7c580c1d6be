#pragma once
// A VkFramebuffer over one colour view. Move-only owner.
#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class Framebuffer {
public:
    Framebuffer() = default;
    Framebuffer(const Context &context, VkRenderPass renderPass, VkImageView view,
                VkExtent2D extent);
    ~Framebuffer();
    Framebuffer(Framebuffer &&other) noexcept;
    Framebuffer &operator=(Framebuffer &&other) noexcept;
    Framebuffer(const Framebuffer &) = delete;
    Framebuffer &operator=(const Framebuffer &) = delete;

    VkFramebuffer handle() const { return framebuffer_; }

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

} // namespace prism::vk
