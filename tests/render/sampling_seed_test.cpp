// The sampling seed (shared/sampling.h: samplingKey, RayTracer::setSeed): another seed is another
// estimate of the same picture, drawn alike by the shader and the CPU reference; a region draws
// what the whole image draws under the same seed; seeds past what the frame carries are refused.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "reference_match.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "shared/gpu_types.h"

namespace prism::test {
namespace {

class SamplingSeed : public GpuTest {};

// The showcase has two spherical area lights (soft shadows) and mirrors; at 4 samples a pixel
// both the pixel jitter and the light points depend on the seed.
Scene showcase() { return loadScene(std::string(PRISM_SCENES_DIR) + "/showcase.scene"); }

TEST_F(SamplingSeed, AnotherSeedIsAnotherEstimateOfTheSamePicture) {
    Scene scene = showcase();
    const uint32_t spp = 4, seed = 12345;
    GpuRender unseeded = renderGpu(context(), scene, kMatchWidth, kMatchHeight, spp);
    GpuRender seeded = renderGpu(context(), scene, kMatchWidth, kMatchHeight, spp, 5, {}, {}, seed);
    // The reference draws the same samples under the seed: the match of the regression suite.
    std::vector<float> cpu = renderCpu(scene, kMatchWidth, kMatchHeight, spp, 5, nullptr, seed);
    ImageDifference same = compareImages(seeded.image.rgba, cpu, kMatchPixelThreshold);
    EXPECT_EQ(same.nonFinite, 0u);
    EXPECT_LE(same.differing, kMatchMaxDifferingPixels) << describe(same);
    EXPECT_LE(same.meanAbsolute, kMatchMaxMeanAbsolute) << describe(same);
    // Against seed 0: other samples (most pixels move), the same picture: two estimates of the
    // image's mean radiance (measured: 0.08% apart).
    ImageDifference other = compareImages(seeded.image.rgba, unseeded.image.rgba, 1e-6);
    EXPECT_GT(other.differingFraction(), 0.5) << describe(other);
    auto meanRadiance = [](const std::vector<float> &rgba) {
        double sum = 0.0;
        for (size_t i = 0; i < rgba.size(); ++i)
            sum += i % 4 == 3 ? 0.0 : rgba[i];
        return sum / double(rgba.size() / 4 * 3);
    };
    double a = meanRadiance(seeded.image.rgba), b = meanRadiance(unseeded.image.rgba);
    EXPECT_NEAR(a / b, 1.0, 0.01) << a << " against " << b;
    EXPECT_EQ(seeded.frame.rays.primary, unseeded.frame.rays.primary);
}

TEST_F(SamplingSeed, ARegionDrawsWhatTheWholeImageDrawsUnderTheSeed) {
    Scene scene = showcase();
    const uint32_t w = 52, h = 37, spp = 2, seed = 777;
    GpuRender whole = renderGpu(context(), scene, w, h, spp, 3, {}, {}, seed);
    TracerOptions options;
    options.region = {13, 9, 40, 30};
    GpuRender part = renderGpu(context(), scene, w, h, spp, 3, {}, options, seed);
    std::vector<float> cut;
    for (uint32_t y = 9; y < 30; ++y)
        cut.insert(cut.end(), whole.image.rgba.begin() + (size_t(y) * w + 13) * 4,
                   whole.image.rgba.begin() + (size_t(y) * w + 40) * 4);
    EXPECT_EQ(part.image.rgba, cut);
}

TEST_F(SamplingSeed, SeedsPastWhatAFrameCarriesAreRefused) {
    Scene scene = showcase();
    EXPECT_THROW(renderGpu(context(), scene, 8, 8, 1, 1, {}, {}, gpu::kMaxSeed + 1), Error);
    EXPECT_NO_THROW(renderGpu(context(), scene, 8, 8, 1, 1, {}, {}, gpu::kMaxSeed));
}

} // namespace
} // namespace prism::test
