#pragma once
// A render pass with one colour attachment and one subpass: enough for a fullscreen pass plus
// an overlay drawn on top. Move-only owner.
#include <vulkan/vulkan.h>

namespace prism::vk {

class Context;

class RenderPass {
public:
    // The attachment starts undefined (every pixel is redrawn) and ends in `finalLayout`.
    RenderPass(const Context &context, VkFormat colorFormat, VkImageLayout finalLayout);
    ~RenderPass();
    RenderPass(RenderPass &&other) noexcept;
    RenderPass &operator=(RenderPass &&other) noexcept;
    RenderPass(const RenderPass &) = delete;
    RenderPass &operator=(const RenderPass &) = delete;

    VkRenderPass handle() const { return renderPass_; }
    VkFormat format() const { return format_; }

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
};

} // namespace prism::vk
