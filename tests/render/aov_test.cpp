// The Z and normal AOVs: from the pixel-centre primary ray, matching the reference.
#include <cmath>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "render_helpers.h"
#include "scene_builders.h"

namespace prism::test {
namespace {

class Aov : public GpuTest {};

TEST_F(Aov, DepthAndNormalOfTheCentreRay) {
    Scene scene = sceneWithDefaultMaterial();
    scene.spheres.push_back(Sphere{{0.0f, 0.0f, 0.0f}, 1.0f, 0});
    scene.camera.eye = {0.0f, 0.0f, 5.0f};
    scene.camera.look = {0.0f, 0.0f, 0.0f};
    TracerOptions options;
    options.writeAov = true;
    const uint32_t size = 15; // odd: the centre pixel's ray is the view axis
    GpuRender gpu = renderGpu(context(), scene, size, size, 4, 5, {}, options);
    const TracedImage &img = gpu.image;
    ASSERT_EQ(img.depth.size(), size_t(size * size));
    size_t centre = (size / 2) * size + size / 2;
    EXPECT_NEAR(img.depth[centre], 4.0f, 1e-5f);
    EXPECT_NEAR(img.normal[centre * 3 + 2], 1.0f, 1e-6f);
    EXPECT_TRUE(std::isinf(img.depth[0]) && img.depth[0] > 0.0f) << "corner misses";
    EXPECT_EQ(img.normal[0], 0.0f);

    RenderSettings settings;
    settings.width = size;
    settings.height = size;
    RenderedImage cpu = renderReference(scene, settings);
    for (size_t p = 0; p < size_t(size * size); ++p) {
        if (std::isinf(cpu.depth[p])) {
            EXPECT_TRUE(std::isinf(img.depth[p])) << p;
            continue;
        }
        EXPECT_NEAR(img.depth[p], cpu.depth[p], 1e-4f) << p;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(img.normal[p * 3 + c], cpu.normal[p][c], 1e-4f) << p;
    }
}

} // namespace
} // namespace prism::test
