#pragma once
// A small scene's shader image held to the CPU reference's, with the tolerance of the scene
// regression test (scene_regression_test.cpp says where it comes from): a pixel differs when a
// channel is off by more than 0.02; 2 such pixels may flip on another CPU's float rounding, a
// third, or a mean over 0.001, fails. Used by the feature tests beside it, each of which states
// what it measured.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "image_compare.h"
#include "render_helpers.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace prism::test {

constexpr double kMatchPixelThreshold = 0.02;
constexpr size_t kMatchMaxDifferingPixels = 2;
constexpr double kMatchMaxMeanAbsolute = 0.001;
constexpr uint32_t kMatchWidth = 64, kMatchHeight = 48;

// The shader's kMatchWidth x kMatchHeight image of `scene`, checked against the reference's.
inline std::vector<float> expectMatchesReference(vk::Context &context, const Scene &scene,
                                                 uint32_t spp = 1) {
    GpuRender gpu = renderGpu(context, scene, kMatchWidth, kMatchHeight, spp);
    std::vector<float> cpu = renderCpu(scene, kMatchWidth, kMatchHeight, spp);
    ImageDifference d = compareImages(gpu.image.rgba, cpu, kMatchPixelThreshold);
    EXPECT_EQ(gpu.frame.loopCutPixels, 0u);
    EXPECT_EQ(d.nonFinite, 0u);
    EXPECT_LE(d.differing, kMatchMaxDifferingPixels) << describe(d);
    EXPECT_LE(d.meanAbsolute, kMatchMaxMeanAbsolute) << describe(d);
    return gpu.image.rgba;
}

} // namespace prism::test
