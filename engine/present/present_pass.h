#pragma once
// Puts the tracer's accumulation image on a swapchain image without a trip through the host:
// a fullscreen triangle whose fragment shader reads the storage image (still in GENERAL
// layout, where the tracer left it), divides by the sample count, clamps and sRGB-encodes.
// A source smaller than the swapchain is magnified (nearest). An overlay may draw into the
// same render pass after it.
#include <functional>
#include <memory>
#include <vector>

#include "vk/context.h"
#include "vk/framebuffer.h"
#include "vk/graphics_pipeline.h"
#include "vk/image.h"
#include "vk/render_pass.h"
#include "vk/swapchain.h"

namespace prism {

class PresentPass {
public:
    PresentPass(const vk::Context &context, const vk::Swapchain &swapchain);

    // After the swapchain was recreated: new framebuffers, and a new render pass and pipeline
    // if its format changed (returns true then: whatever was built on renderPass() must be
    // rebuilt too). No frame may be in flight.
    bool resetSwapchain(const vk::Swapchain &swapchain);
    // The image to show. No frame in flight may still read the previous one.
    void setSource(const vk::Image &accumulation);

    // Records, on the swapchain image `imageIndex`: a barrier from the tracer's writes to this
    // pass's reads, the fullscreen draw, `overlay` (inside the render pass) and a barrier that
    // keeps the next frame's tracer writes after this pass's reads.
    void record(VkCommandBuffer commands, uint32_t imageIndex,
                const std::function<void(VkCommandBuffer)> &overlay = {}) const;

    VkRenderPass renderPass() const { return renderPass_->handle(); }

private:
    void buildPipeline(const vk::Swapchain &swapchain);

    const vk::Context &context_;
    std::unique_ptr<vk::RenderPass> renderPass_;
    std::unique_ptr<vk::GraphicsPipeline> pipeline_;
    std::vector<vk::Framebuffer> framebuffers_;
    VkExtent2D extent_{0, 0};
    VkImage source_ = VK_NULL_HANDLE;
    VkExtent2D sourceExtent_{0, 0};
};

} // namespace prism
