// The camera model of docs/scene-format.md: primary ray directions, ortho origins, and the
// stratified sample positions shared with the shader.
#include <cmath>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "expect_near.h"
#include "reference/camera_model.h"
#include "shared/sampling.h"

namespace prism {
namespace {

using test::expectNear;

Camera obliqueCamera() {
    Camera camera;
    camera.eye = {1.0f, 2.0f, 3.0f};
    camera.look = {-2.0f, 0.5f, 1.0f};
    camera.up = {0.0f, 1.0f, 0.2f};
    camera.fovDegrees = 50.0f;
    return camera;
}

TEST(CameraModel, CentrePixelRayGoesAlongForward) {
    Camera camera = obliqueCamera();
    const int w = 15, h = 9; // odd: the centre of pixel (7, 4) is the image centre
    CameraFrame frame = makeCameraFrame(camera, w, h);
    Ray ray = cameraRay(frame, glm::dvec2(7.5, 4.5));
    glm::dvec3 forward = glm::normalize(glm::dvec3(camera.look) - glm::dvec3(camera.eye));
    expectNear(ray.origin, glm::dvec3(camera.eye), 0.0);
    expectNear(ray.dir, forward, 1e-15);
}

// Each pixel centre's direction, written out from the spec's formula.
TEST(CameraModel, PixelRaysFollowTheSpecFormula) {
    Camera camera = obliqueCamera();
    const int w = 20, h = 12;
    CameraFrame frame = makeCameraFrame(camera, w, h);
    glm::dvec3 forward = glm::normalize(glm::dvec3(camera.look) - glm::dvec3(camera.eye));
    glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
    glm::dvec3 trueUp = glm::cross(right, forward);
    double halfHeight = std::tan(glm::radians(50.0) / 2.0), aspect = double(w) / double(h);
    for (auto [i, j] : {std::pair{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}, {7, 3}}) {
        double u = (i + 0.5) / w, v = (j + 0.5) / h;
        glm::dvec3 expected = glm::normalize(forward + (2 * u - 1) * halfHeight * aspect * right +
                                             (1 - 2 * v) * halfHeight * trueUp);
        SCOPED_TRACE(testing::Message() << "pixel " << i << "," << j);
        expectNear(cameraRay(frame, glm::dvec2(i, j) + 0.5).dir, expected, 1e-14);
    }
    // Top-left looks up and to the left.
    Ray topLeft = cameraRay(frame, glm::dvec2(0.5, 0.5));
    EXPECT_GT(glm::dot(topLeft.dir, trueUp), 0.0);
    EXPECT_LT(glm::dot(topLeft.dir, right), 0.0);
}

TEST(CameraModel, OrthoRaysAreParallelAndStartOnTheImagePlane) {
    Camera camera;
    camera.eye = {0.0f, 0.0f, 5.0f};
    camera.look = {0.0f, 0.0f, 0.0f};
    camera.orthoHeight = 4.0f;
    const int w = 8, h = 4; // 1-unit pixels
    CameraFrame frame = makeCameraFrame(camera, w, h);
    EXPECT_TRUE(frame.ortho);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            Ray ray = cameraRay(frame, glm::dvec2(i, j) + 0.5);
            expectNear(ray.dir, glm::dvec3(0.0, 0.0, -1.0), 0.0);
            // origin = eye + (2u - 1)(H/2)a right + (1 - 2v)(H/2) trueUp
            double u = (i + 0.5) / w, v = (j + 0.5) / h;
            glm::dvec3 expected(0.0 + (2 * u - 1) * 2.0 * 2.0, (1 - 2 * v) * 2.0, 5.0);
            expectNear(ray.origin, expected, 1e-14);
        }
    // Neighbouring pixels are one unit apart on the plane.
    Ray a = cameraRay(frame, {0.5, 0.5}), b = cameraRay(frame, {1.5, 1.5});
    expectNear(b.origin - a.origin, glm::dvec3(1.0, -1.0, 0.0), 1e-14);
}

TEST(CameraModel, OneSampleIsThePixelCentre) {
    glm::dvec2 p = pixelSamplePosition(3, 7, 123, 0, 1);
    EXPECT_EQ(p, glm::dvec2(3.5, 7.5));
}

// Every sample stays in its pixel, and N = columns x rows samples cover every stratum once.
TEST(CameraModel, SamplePositionsStayInThePixelAndCoverTheStrata) {
    for (uint32_t spp : {4u, 9u, 16u, 6u, 12u}) {
        uint32_t columns = gpu::strataColumns(spp), rows = gpu::strataRows(spp);
        ASSERT_GE(columns * rows, spp);
        for (auto [px, py] : {std::pair{0, 0}, {5, 2}, {100, 37}}) {
            uint32_t pixelIndex = uint32_t(py * 128 + px);
            std::set<std::pair<int, int>> strata;
            for (uint32_t s = 0; s < spp; ++s) {
                glm::dvec2 p = pixelSamplePosition(px, py, pixelIndex, s, spp);
                glm::dvec2 local = p - glm::dvec2(px, py);
                EXPECT_GE(local.x, 0.0);
                EXPECT_LT(local.x, 1.0);
                EXPECT_GE(local.y, 0.0);
                EXPECT_LT(local.y, 1.0);
                int cx = int(std::floor(local.x * columns)), cy = int(std::floor(local.y * rows));
                EXPECT_EQ(cx, int(s % columns)) << "spp " << spp << " sample " << s;
                EXPECT_EQ(cy, int(s / columns)) << "spp " << spp << " sample " << s;
                strata.insert({cx, cy});
            }
            EXPECT_EQ(strata.size(), size_t(spp)) << "spp " << spp;
        }
    }
    EXPECT_EQ(gpu::strataColumns(16), 4u);
    EXPECT_EQ(gpu::strataRows(16), 4u);
    EXPECT_EQ(gpu::strataColumns(6), 2u);
    EXPECT_EQ(gpu::strataRows(6), 3u);
}

// Jitter is a hash of (pixel, sample): different pixels get different offsets.
TEST(CameraModel, JitterDiffersBetweenPixels) {
    glm::dvec2 a = pixelSamplePosition(0, 0, 0, 0, 4) - glm::dvec2(0, 0);
    glm::dvec2 b = pixelSamplePosition(1, 0, 1, 0, 4) - glm::dvec2(1, 0);
    EXPECT_NE(a, b);
}

} // namespace
} // namespace prism
