// Image regression: every shipped scene rendered by the shader (lavapipe, validation on) must
// match the double-precision CPU reference at a small size.
//
// Tolerance, and why: the shader works in float, the reference in double. Where a pixel's ray
// grazes a silhouette or a shadow boundary the two can legitimately pick different sides, so
// up to 1% of pixels may differ by more than 0.02 (in linear radiance); everywhere else the
// difference is rounding, so the mean absolute difference must stay under 0.002.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "shipped_scenes.h"

namespace prism::test {
namespace {

constexpr double kPixelThreshold = 0.02;
constexpr double kMaxDifferingFraction = 0.01;
constexpr double kMaxMeanAbsolute = 0.002;

class SceneRegression : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SceneRegression, ShaderMatchesCpuReference) {
    std::filesystem::path path = std::filesystem::path(PRISM_SCENES_DIR) / (GetParam() + ".scene");
    Scene scene = loadScene(path);
    // Scenes with soft shadows also check the shared sample sequence (4 samples per pixel).
    bool soft = false;
    for (const Light &l : scene.lights)
        soft = soft || l.radius > 0.0f;
    uint32_t spp = soft ? 4 : 1;
    const uint32_t width = 64, height = 48;

    GpuRender gpu = renderGpu(context(), scene, width, height, spp);
    EXPECT_EQ(gpu.frame.overBudgetPixels, 0u);
    RayCounts cpuRays;
    std::vector<float> cpu = renderCpu(scene, width, height, spp, 5, &cpuRays);

    ImageDifference d = compareImages(gpu.image.rgba, cpu, kPixelThreshold);
    EXPECT_EQ(d.nonFinite, 0u);
    EXPECT_LE(d.differingFraction(), kMaxDifferingFraction) << describe(d);
    EXPECT_LE(d.meanAbsolute, kMaxMeanAbsolute) << describe(d);
    // Both count the rays they trace; the counts agree up to the differing pixels.
    EXPECT_EQ(gpu.frame.rays.primary, cpuRays.primary);
    EXPECT_NEAR(double(gpu.frame.rays.shadow), double(cpuRays.shadow),
                0.02 * double(cpuRays.shadow) + 8.0);
    EXPECT_NEAR(double(gpu.frame.rays.secondary), double(cpuRays.secondary),
                0.02 * double(cpuRays.secondary) + 8.0);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, SceneRegression, ::testing::ValuesIn(shippedScenes()),
                         [](const auto &info) { return info.param; });

} // namespace
} // namespace prism::test
