// The reference renderer as a whole: ray counts, AOVs, determinism across threads, scale
// invariance, progress reports and input checks.
#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "reference/reference_renderer.h"
#include "reference_test_scenes.h"
#include "scene/scene_origin.h"
#include "scene_transform.h"

namespace prism {
namespace {

RenderSettings settings(int w, int h, uint32_t spp = 1, uint32_t depth = 5) {
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.samplesPerPixel = spp;
    s.maxDepth = depth;
    return s;
}

// Ortho camera straight down at a floor: every pixel hits it, one light above.
Scene floorScene(float reflect) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.materials[0].reflect = reflect;
    scene.planes.push_back(Plane{{0, 0, 0}, {0, 1, 0}, 0});
    scene.lights.push_back(Light{{0, 5, 0}, {1, 1, 1}, 0.0f});
    scene.camera.eye = {0, 3, 0};
    scene.camera.look = {0, 0, 0};
    scene.camera.up = {0, 0, -1};
    scene.camera.orthoHeight = 2.0f;
    return scene;
}

TEST(ReferenceRenderer, RayCountsOfAKnownScene) {
    RenderedImage image = renderReference(floorScene(0.0f), settings(4, 4, 1, 1));
    EXPECT_EQ(image.rays.primary, 16u);
    EXPECT_EQ(image.rays.shadow, 16u);
    EXPECT_EQ(image.rays.secondary, 0u);
    // Reflected rays go up and miss: one secondary per sample, no extra shadow rays.
    image = renderReference(floorScene(0.5f), settings(4, 4, 3, 3));
    EXPECT_EQ(image.rays.primary, 48u);
    EXPECT_EQ(image.rays.shadow, 48u);
    EXPECT_EQ(image.rays.secondary, 48u);
    EXPECT_EQ(image.rays.total(), 144u);
    // Depth 1 traces no reflection even with reflect > 0.
    image = renderReference(floorScene(0.5f), settings(4, 4, 1, 1));
    EXPECT_EQ(image.rays.secondary, 0u);
}

TEST(ReferenceRenderer, ImageShapeAndAlpha) {
    RenderedImage image = renderReference(test::mixedScene(), settings(7, 5));
    EXPECT_EQ(image.width, 7);
    EXPECT_EQ(image.height, 5);
    ASSERT_EQ(image.rgba.size(), 35u);
    ASSERT_EQ(image.depth.size(), 35u);
    ASSERT_EQ(image.normal.size(), 35u);
    for (const glm::vec4 &p : image.rgba) {
        EXPECT_EQ(p.a, 1.0f);
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(std::isfinite(p[c]) && p[c] >= 0.0f);
    }
}

TEST(ReferenceRenderer, DepthAndNormalOfThePixelCentreRay) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.spheres.push_back(Sphere{{0, 0, 0}, 1.0f, 0});
    const int size = 15; // odd: the centre pixel's ray is the view axis
    RenderedImage image = renderReference(scene, settings(size, size, 4));
    size_t centre = size_t(size / 2) * size + size / 2;
    EXPECT_FLOAT_EQ(image.depth[centre], 4.0f);
    EXPECT_EQ(image.normal[centre], glm::vec3(0, 0, 1));
    EXPECT_TRUE(std::isinf(image.depth[0]) && image.depth[0] > 0.0f) << "corner misses";
    EXPECT_EQ(image.normal[0], glm::vec3(0.0f));

    // From inside the sphere the normal is flipped to face the ray.
    scene.camera.eye = {0, 0, 0.5f};
    scene.camera.look = {0, 0, -1};
    image = renderReference(scene, settings(size, size));
    EXPECT_FLOAT_EQ(image.depth[centre], 1.5f);
    EXPECT_EQ(image.normal[centre], glm::vec3(0, 0, 1));
    for (size_t p = 0; p < image.normal.size(); ++p)
        EXPECT_NEAR(glm::length(image.normal[p]), 1.0f, 1e-6f) << p;
}

// Rows go to threads in whatever order they finish; the result must not depend on it, and it
// must equal tracing each sample on its own.
TEST(ReferenceRenderer, DeterministicAcrossRunsAndThreads) {
    Scene scene = test::mixedScene(0.4f); // area light: sampled shadow rays too
    RenderSettings s = settings(24, 18, 4, 5);
    RenderedImage a = renderReference(scene, s), b = renderReference(scene, s);
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    for (size_t p = 0; p < a.rgba.size(); ++p) {
        ASSERT_EQ(a.rgba[p], b.rgba[p]) << p;
        ASSERT_EQ(a.depth[p], b.depth[p]) << p;
        ASSERT_EQ(a.normal[p], b.normal[p]) << p;
    }
    EXPECT_EQ(a.rays.primary, b.rays.primary);
    EXPECT_EQ(a.rays.shadow, b.rays.shadow);
    EXPECT_EQ(a.rays.secondary, b.rays.secondary);

    // The renderer traces relative to the camera (reference_renderer.h): so does this.
    Scene moved = scene;
    moveOrigin(moved, scene.camera.eye);
    CameraFrame frame = makeCameraFrame(moved.camera, s.width, s.height);
    RayCounts rays;
    for (int py = 0; py < s.height; ++py)
        for (int px = 0; px < s.width; ++px) {
            glm::dvec3 sum(0.0);
            for (uint32_t k = 0; k < s.samplesPerPixel; ++k)
                sum +=
                    tracePixelSample(moved, frame, px, py, k, s.samplesPerPixel, s.maxDepth, rays);
            glm::vec3 expected(sum / double(s.samplesPerPixel));
            ASSERT_EQ(glm::vec3(a.rgba[size_t(py) * size_t(s.width) + size_t(px)]), expected)
                << px << "," << py;
        }
    EXPECT_EQ(rays.primary, a.rays.primary);
    EXPECT_EQ(rays.shadow, a.rays.shadow);
    EXPECT_EQ(rays.secondary, a.rays.secondary);
    EXPECT_GT(a.rays.secondary, 0u);
}

// Offsets are relative to |P|, so scaling the whole scene changes nothing but rounding.
TEST(ReferenceRenderer, SameImageAtEveryScale) {
    Scene base = test::mixedScene(0.3f);
    RenderSettings s = settings(32, 24, 4, 5);
    RenderedImage reference = renderReference(base, s);
    for (float scale : {1e-3f, 1e3f}) {
        RenderedImage image = renderReference(test::transformed(base, scale), s);
        double largest = 0.0;
        for (size_t p = 0; p < image.rgba.size(); ++p)
            for (int c = 0; c < 3; ++c)
                largest =
                    std::max(largest, std::abs(double(image.rgba[p][c]) - reference.rgba[p][c]));
        EXPECT_LE(largest, 1e-6) << "scale " << scale;
        EXPECT_EQ(image.rays.shadow, reference.rays.shadow) << "scale " << scale;
        EXPECT_EQ(image.rays.secondary, reference.rays.secondary) << "scale " << scale;
    }
}

// Positions are double and the reference traces relative to the camera: moved up to 1e7 away
// the picture is the unit scene's (an offset relative to |P| in the file's coordinates would
// be 1e7 times larger there, and lose contact shadows).
TEST(ReferenceRenderer, SameImageFarFromTheOrigin) {
    Scene base = test::mixedScene(0.3f);
    RenderSettings s = settings(32, 24, 4, 5);
    RenderedImage reference = renderReference(base, s);
    for (glm::dvec3 offset : {glm::dvec3(1e4), glm::dvec3(-1e6, 1e5, 1e6), glm::dvec3(0, 0, 1e7)}) {
        RenderedImage image = renderReference(test::transformed(base, 1.0, offset), s);
        double largest = 0.0;
        for (size_t p = 0; p < image.rgba.size(); ++p)
            for (int c = 0; c < 3; ++c)
                largest =
                    std::max(largest, std::abs(double(image.rgba[p][c]) - reference.rgba[p][c]));
        EXPECT_LE(largest, 1e-6) << "offset " << offset.x << " " << offset.y << " " << offset.z;
        EXPECT_EQ(image.rays.shadow, reference.rays.shadow);
        EXPECT_EQ(image.rays.secondary, reference.rays.secondary);
    }
}

TEST(ReferenceRenderer, ProgressFromTheCallingThreadUpToOne) {
    std::vector<double> fractions;
    std::thread::id caller = std::this_thread::get_id();
    bool otherThread = false;
    renderReference(test::mixedScene(), settings(16, 40), [&](double f) {
        otherThread = otherThread || std::this_thread::get_id() != caller;
        fractions.push_back(f);
    });
    ASSERT_FALSE(fractions.empty());
    EXPECT_FALSE(otherThread);
    EXPECT_EQ(fractions.back(), 1.0);
    for (size_t i = 1; i < fractions.size(); ++i)
        EXPECT_GE(fractions[i], fractions[i - 1]);
    EXPECT_EQ(std::count(fractions.begin(), fractions.end(), 1.0), 1);
}

TEST(ReferenceRenderer, RejectsBadSettingsAndDanglingIndices) {
    Scene scene = test::mixedScene();
    EXPECT_THROW(renderReference(scene, settings(0, 4)), Error);
    EXPECT_THROW(renderReference(scene, settings(4, 4, 0)), Error);
    EXPECT_THROW(renderReference(scene, settings(4, 4, 1, 0)), Error);
    scene.spheres[0].material = 99;
    EXPECT_THROW(renderReference(scene, settings(4, 4)), Error);
    scene = test::mixedScene();
    scene.materials[1].texture = 0; // no textures loaded
    EXPECT_THROW(renderReference(scene, settings(4, 4)), Error);
}

} // namespace
} // namespace prism
