// Hit points, normals, texture coordinates, texture lookups and ray offsets of the reference.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "expect_near.h"
#include "reference/surface_reference.h"
#include "scene_builders.h"
#include "shared/gpu_types.h"

namespace prism::reference {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using test::expectNear;

TEST(SurfaceAt, SpherePointNormalAndUV) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.spheres.push_back(Sphere{{1, 2, 3}, 2.0f, 0});
    Ray ray{{10, 2, 3}, {-1, 0, 0}};
    Hit hit;
    ASSERT_TRUE(traceClosest(scene, ray, kInf, hit));
    Surface s = surfaceAt(scene, ray, hit);
    expectNear(s.position, {3, 2, 3}, 1e-14);
    expectNear(s.geometricNormal, {1, 0, 0}, 1e-15);
    // n = +x: u = 0.5 + atan2(0, 1) / 2pi, v = 0.5 + asin(0) / pi
    EXPECT_NEAR(s.uv.x, 0.5, 1e-15);
    EXPECT_NEAR(s.uv.y, 0.5, 1e-15);
    // The top: v = 1.
    Ray down{{1, 10, 3}, {0, -1, 0}};
    ASSERT_TRUE(traceClosest(scene, down, kInf, hit));
    EXPECT_NEAR(surfaceAt(scene, down, hit).uv.y, 1.0, 1e-7);
}

TEST(SurfaceAt, PlanePointIsOnThePlane) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.planes.push_back(Plane{{0, 0.1f, 0}, {0, 1, 0}, 0});
    glm::dvec3 dir = glm::normalize(glm::dvec3(1.0, -0.3, 0.7));
    Ray ray{{1000.0, 57.0, -3000.0}, dir};
    Hit hit;
    ASSERT_TRUE(traceClosest(scene, ray, kInf, hit));
    Surface s = surfaceAt(scene, ray, hit);
    EXPECT_EQ(s.position.y, double(0.1f)) << "projected exactly onto y = 0.1";
    expectNear(s.geometricNormal, {0, 1, 0}, 0.0);
}

TEST(SurfaceAt, TriangleInterpolatesNormalsAndUVs) {
    Scene scene = test::sceneWithDefaultMaterial();
    test::addTriangle(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);
    Ray ray{{0.25, 0.5, 1}, {0, 0, -1}};
    Hit hit;
    ASSERT_TRUE(traceClosest(scene, ray, kInf, hit));
    Surface s = surfaceAt(scene, ray, hit);
    expectNear(s.position, {0.25, 0.5, 0}, 1e-15);
    expectNear(s.geometricNormal, {0, 0, 1}, 0.0);
    EXPECT_NEAR(s.uv.x, 0.25, 1e-15) << "no vt: barycentric (b1, b2)";
    EXPECT_NEAR(s.uv.y, 0.5, 1e-15);

    TriangleShading &t = shadingFor(scene.triangles[0], scene.triangleShading);
    t.hasNormals = true;
    t.n[0] = {0, 0, 1};
    t.n[1] = {1, 0, 1};
    t.n[2] = {0, 1, 1};
    t.hasUVs = true;
    t.uv[0] = {0.5f, 0.5f};
    t.uv[1] = {1.0f, 0.5f};
    t.uv[2] = {0.5f, 1.0f};
    s = surfaceAt(scene, ray, hit);
    expectNear(s.shadingNormal, glm::normalize(glm::dvec3(0.25, 0.5, 1.0)), 1e-15);
    expectNear(s.geometricNormal, {0, 0, 1}, 0.0);
    EXPECT_NEAR(s.uv.x, 0.5 + 0.25 * 0.5, 1e-15);
    EXPECT_NEAR(s.uv.y, 0.5 + 0.5 * 0.5, 1e-15);
}

TEST(PlaneUV, AxesFollowTheLeastAlignedWorldAxis) {
    // n = +y: least aligned is x (ties x before z); a1 = normalize(y x x) = -z, a2 = y x a1 = -x.
    glm::dvec2 uv = planeUV({2.0, 0.0, 3.0}, {0, 1, 0});
    EXPECT_DOUBLE_EQ(uv.x, -3.0);
    EXPECT_DOUBLE_EQ(uv.y, -2.0);
    // n = +x: least aligned is y; a1 = x x y = z, a2 = x x z = -y.
    uv = planeUV({0.0, 5.0, 7.0}, {1, 0, 0});
    EXPECT_DOUBLE_EQ(uv.x, 7.0);
    EXPECT_DOUBLE_EQ(uv.y, -5.0);
}

// 2x2 texture stored top row first: top = red, green; bottom = blue, white.
Texture quadTexture() {
    Texture t;
    t.width = 2;
    t.height = 2;
    t.texels = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    return t;
}

TEST(TextureColor, TexelCentresBottomRowFirstAndWrap) {
    Texture t = quadTexture();
    expectNear(textureColor(t, {0.25, 0.25}), {0, 0, 1}, 1e-15, "v = 0 is the bottom row");
    expectNear(textureColor(t, {0.75, 0.25}), {1, 1, 1}, 1e-15);
    expectNear(textureColor(t, {0.25, 0.75}), {1, 0, 0}, 1e-15);
    expectNear(textureColor(t, {0.75, 0.75}), {0, 1, 0}, 1e-15);
    expectNear(textureColor(t, {0.25 + 3.0, 0.75 - 2.0}), {1, 0, 0}, 1e-14, "wraps");
    expectNear(textureColor(t, {-0.25, -0.25}), {0, 1, 0}, 1e-14, "negative wraps");
}

TEST(TextureColor, BilinearAcrossTheWrap) {
    Texture t = quadTexture();
    // Halfway between bottom-left blue and bottom-right white.
    expectNear(textureColor(t, {0.5, 0.25}), {0.5, 0.5, 1.0}, 1e-15);
    // u = 0 is halfway between the last column and the first (wrap): white and blue again.
    expectNear(textureColor(t, {0.0, 0.25}), {0.5, 0.5, 1.0}, 1e-15);
    // The very corner mixes all four.
    expectNear(textureColor(t, {0.0, 0.0}), {0.5, 0.5, 0.5}, 1e-15);
}

TEST(OffsetOrigin, RelativeToTheLargestCoordinateOnTheLeavingSide) {
    glm::dvec3 p(1000.0, 2.0, -3.0), n(0, 1, 0);
    double eps = 1000.0 * PRISM_OFFSET_RELATIVE;
    expectNear(offsetOrigin(p, n, {0, 1, 0}), p + glm::dvec3(0, eps, 0), 0.0);
    expectNear(offsetOrigin(p, n, {0.3, -1, 0}), p - glm::dvec3(0, eps, 0), 0.0);
    // Scale-free: the offset shrinks with the coordinates.
    expectNear(offsetOrigin(p * 1e-6, n, {0, 1, 0}), p * 1e-6 + glm::dvec3(0, eps * 1e-6, 0),
               1e-24);
    // At the origin the floor keeps it non-zero.
    EXPECT_GT(offsetOrigin(glm::dvec3(0.0), n, {0, 1, 0}).y, 0.0);
}

} // namespace
} // namespace prism::reference
