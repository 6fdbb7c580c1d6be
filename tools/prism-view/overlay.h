#pragma once
// The overlay: Dear ImGui (GLFW + Vulkan backends) drawn into the present pass's render pass.
// Shows what the frame costs and what the tracer is doing, and the feature toggles.
#include <cstdint>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include "feature_toggles.h"
#include "vk/context.h"
#include "vk/descriptor_pool.h"

namespace prism {

class Window;

struct OverlayStats {
    double fps = 0.0;
    double msPerFrame = 0.0;
    double mraysPerSecond = 0.0;
    uint32_t samples = 0, samplesTarget = 0;
    std::string grid; // "48x12x40" or "off"
    // What the scene holds ("4 spheres, 1 plane, 12176 triangles, 3 instances of 4968") and
    // what its arrays take on the device.
    std::string geometry;
    uint64_t sceneBytes = 0;
    std::string device;
    std::string presentMode;
    uint32_t width = 0, height = 0; // traced image
    uint32_t traceScale = 1;        // > 1: a moving camera's reduced image
    std::string scene;
    std::string frame; // "frame 12 of 48" for an animated scene, else empty
    std::string sceneError; // FILE:LINE message of the last failed load, else empty
    uint64_t loopCutPixels = 0;
    std::string notice; // e.g. "saved prism-view-....exr"
};

class Overlay {
public:
    Overlay(Window &window, const vk::Context &context, VkRenderPass renderPass,
            uint32_t framesInFlight);
    ~Overlay();
    Overlay(const Overlay &) = delete;
    Overlay &operator=(const Overlay &) = delete;

    // The swapchain format changed: the UI pipeline is rebuilt for the new render pass.
    void setRenderPass(VkRenderPass renderPass);

    // Builds this frame's UI (also when hidden, so input stays consistent); returns true when
    // a toggle changed. Call once per frame before record().
    bool build(const OverlayStats &stats, FeatureToggles &toggles, bool visible);
    void record(VkCommandBuffer commands);

    bool wantsMouse() const;
    bool wantsKeyboard() const;

private:
    void initRenderer(VkRenderPass renderPass);
    const vk::Context &context_;
    uint32_t framesInFlight_;
    std::unique_ptr<vk::DescriptorPool> pool_;
    bool rendererReady_ = false;
};

} // namespace prism
