#pragma once
// Rendering one scene on both backends, for comparisons.
#include <vector>

#include <gtest/gtest.h>

#include "accel/bounds.h"
#include "accel/grid.h"
#include "reference/reference_renderer.h"
#include "render/ray_tracer.h"
#include "scene/scene.h"
#include "scene/scene_origin.h"

namespace prism::test {

// The same boxes in the same order, bit for bit (extents, render/traced_tiles.h).
inline bool sameBoxes(const std::vector<Aabb> &a, const std::vector<Aabb> &b) {
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].min != b[i].min || a[i].max != b[i].max)
            return false;
    return true;
}

struct GpuRender {
    TracedImage image;
    FrameResult frame;
};

// As prism-render does: the scene centred on the camera (scene/scene_origin.h), then its grid.
inline GpuRender renderGpu(vk::Context &context, Scene scene, uint32_t width, uint32_t height,
                           uint32_t spp = 1, uint32_t depth = 5, GridOptions gridOptions = {},
                           TracerOptions options = {}, uint32_t seed = 0) {
    centerOnCamera(scene);
    Grid grid = buildGrid(scene, gridOptions);
    options.maxDepth = depth;
    RayTracer tracer(context, scene, grid, width, height, options);
    tracer.setSeed(seed);
    GpuRender out;
    out.frame = tracer.renderFrame(scene.camera, spp);
    out.image = tracer.readback(spp);
    return out;
}

// Two renders of one frame that must agree bit for bit: image, AOVs and ray counts.
inline void expectSameFrame(const GpuRender &a, const GpuRender &b) {
    EXPECT_EQ(a.image.rgba, b.image.rgba);
    EXPECT_EQ(a.image.depth, b.image.depth);
    EXPECT_EQ(a.image.normal, b.image.normal);
    EXPECT_EQ(a.frame.rays.primary, b.frame.rays.primary);
    EXPECT_EQ(a.frame.rays.shadow, b.frame.rays.shadow);
    EXPECT_EQ(a.frame.rays.secondary, b.frame.rays.secondary);
}

// The same centred scene as renderGpu gives the GPU.
inline std::vector<float> renderCpu(Scene scene, int width, int height, uint32_t spp = 1,
                                    uint32_t depth = 5, RayCounts *rays = nullptr,
                                    uint32_t seed = 0) {
    centerOnCamera(scene);
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.samplesPerPixel = spp;
    settings.maxDepth = depth;
    settings.seed = seed;
    RenderedImage image = renderReference(scene, settings);
    if (rays)
        *rays = image.rays;
    std::vector<float> rgba;
    rgba.reserve(image.rgba.size() * 4);
    for (const glm::vec4 &p : image.rgba)
        rgba.insert(rgba.end(), {p.r, p.g, p.b, p.a});
    return rgba;
}

} // namespace prism::test
