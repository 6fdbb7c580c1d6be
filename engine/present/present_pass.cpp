#include "present/present_pass.h"

#include "core/error.h"
#include "shaders/fullscreen.vert.spv.h"
#include "shaders/present.frag.spv.h"
#include "vk/barriers.h"

namespace prism {
PresentPass::PresentPass(const vk::Context &context, const vk::Swapchain &swapchain)
    : context_(context) {
    resetSwapchain(swapchain);
}

void PresentPass::buildPipeline(const vk::Swapchain &swapchain) {
    pipeline_.reset();
    renderPass_ = std::make_unique<vk::RenderPass>(context_, swapchain.format(),
                                                   VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    vk::GraphicsPipelineDesc desc;
    desc.vertexSpirv =
        std::span<const uint32_t>(kFullscreenVertSpv, sizeof(kFullscreenVertSpv) / 4);
    desc.fragmentSpirv = std::span<const uint32_t>(kPresentFragSpv, sizeof(kPresentFragSpv) / 4);
    desc.bindings = {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    desc.fragmentSpecialization = {{0u, swapchain.encodesSrgb() ? 0u : 1u}}; // present.frag
    desc.pushConstantBytes = 2 * sizeof(float); // image size / framebuffer size
    desc.renderPass = renderPass_->handle();
    pipeline_ = std::make_unique<vk::GraphicsPipeline>(context_, desc);
    source_ = VK_NULL_HANDLE; // a new descriptor set: bind the source again
}

bool PresentPass::resetSwapchain(const vk::Swapchain &swapchain) {
    framebuffers_.clear();
    bool rebuilt = !renderPass_ || renderPass_->format() != swapchain.format();
    if (rebuilt)
        buildPipeline(swapchain);
    extent_ = swapchain.extent();
    for (uint32_t i = 0; i < swapchain.imageCount(); ++i)
        framebuffers_.emplace_back(context_, renderPass_->handle(), swapchain.view(i), extent_);
    return rebuilt;
}

void PresentPass::setSource(const vk::Image &accumulation) {
    if (accumulation.format() != VK_FORMAT_R32G32B32A32_SFLOAT)
        throw Error("the present pass shows rgba32f accumulation images only");
    pipeline_->bindStorageImage(0, accumulation.view());
    source_ = accumulation.handle();
    sourceExtent_ = {accumulation.width(), accumulation.height()};
}

void PresentPass::record(VkCommandBuffer commands, uint32_t imageIndex,
                         const std::function<void(VkCommandBuffer)> &overlay) const {
    if (!source_)
        throw Error("PresentPass::record before setSource");
    vk::imageBarrier(commands, source_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);

    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = renderPass_->handle();
    begin.framebuffer = framebuffers_.at(imageIndex).handle();
    begin.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    VkViewport viewport{0.0f, 0.0f, float(extent_.width), float(extent_.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, extent_};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    pipeline_->bind(commands);
    float imagePerFragment[2] = {float(sourceExtent_.width) / float(extent_.width),
                                 float(sourceExtent_.height) / float(extent_.height)};
    vkCmdPushConstants(commands, pipeline_->layout(), VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(imagePerFragment), imagePerFragment);
    vkCmdDraw(commands, 3, 1, 0, 0);
    if (overlay)
        overlay(commands);
    vkCmdEndRenderPass(commands);

    // Write-after-read: the next frame's samples overwrite what this pass read.
    vk::imageBarrier(commands, source_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

} // namespace prism
