#include "vk/render_pass.h"

#include <utility>

#include "vk/context.h"
#include "vk/vk_check.h"

namespace prism::vk {

RenderPass::RenderPass(const Context &context, VkFormat colorFormat, VkImageLayout finalLayout)
    : device_(context.device()), format_(colorFormat) {
    VkAttachmentDescription color{};
    color.format = colorFormat;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; // the fullscreen pass covers every pixel
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    color.finalLayout = finalLayout;

    VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;

    // The layout transition at the start waits for the stage that waits on image acquisition.
    VkSubpassDependency acquire{};
    acquire.srcSubpass = VK_SUBPASS_EXTERNAL;
    acquire.dstSubpass = 0;
    acquire.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    acquire.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    acquire.srcAccessMask = 0;
    acquire.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &acquire;
    VK_CHECK(vkCreateRenderPass(device_, &info, nullptr, &renderPass_));
}

RenderPass::~RenderPass() {
    release();
}

RenderPass::RenderPass(RenderPass &&other) noexcept {
    *this = std::move(other);
}

RenderPass &RenderPass::operator=(RenderPass &&other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        renderPass_ = std::exchange(other.renderPass_, VK_NULL_HANDLE);
        format_ = other.format_;
    }
    return *this;
}

void RenderPass::release() {
    if (renderPass_)
        vkDestroyRenderPass(device_, renderPass_, nullptr);
    renderPass_ = VK_NULL_HANDLE;
}

} // namespace prism::vk
