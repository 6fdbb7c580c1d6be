// Ray/primitive tests and brute-force scene queries of the CPU reference.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "reference/intersect_reference.h"
#include "reference/scene_query.h"
#include "scene_builders.h"

namespace prism::reference {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(IntersectSphere, FromOutside) {
    double t = 0.0;
    ASSERT_TRUE(intersectSphere({{0, 0, 5}, {0, 0, -1}}, {0, 0, 0}, 1.0, kInf, t));
    EXPECT_DOUBLE_EQ(t, 4.0);
}

TEST(IntersectSphere, FromInsideHitsTheFarSide) {
    double t = 0.0;
    ASSERT_TRUE(intersectSphere({{0.2, 0, 0}, {1, 0, 0}}, {0, 0, 0}, 1.0, kInf, t));
    EXPECT_NEAR(t, 0.8, 1e-15);
}

TEST(IntersectSphere, BehindTheRayOrBeyondTMaxMisses) {
    double t = 0.0;
    EXPECT_FALSE(intersectSphere({{0, 0, 5}, {0, 0, 1}}, {0, 0, 0}, 1.0, kInf, t));
    EXPECT_FALSE(intersectSphere({{0, 0, 5}, {0, 0, -1}}, {0, 0, 0}, 1.0, 3.9, t));
}

TEST(IntersectSphere, NearlyTangentRays) {
    double t = 0.0;
    const double y = 1.0 - 1e-9;
    ASSERT_TRUE(intersectSphere({{0, y, 5}, {0, 0, -1}}, {0, 0, 0}, 1.0, kInf, t));
    EXPECT_NEAR(t, 5.0 - std::sqrt(1.0 - y * y), 1e-12);
    EXPECT_FALSE(intersectSphere({{0, 1.0 + 1e-9, 5}, {0, 0, -1}}, {0, 0, 0}, 1.0, kInf, t));
}

// The stable form keeps full precision far from a small sphere.
TEST(IntersectSphere, FarAwaySmallSphere) {
    double t = 0.0;
    ASSERT_TRUE(intersectSphere({{0, 0, 1e6}, {0, 0, -1}}, {0, 0, 0}, 1e-3, kInf, t));
    EXPECT_NEAR(t, 1e6 - 1e-3, 1e-9);
}

TEST(IntersectPlane, HitParallelAndBehind) {
    PlaneEquation floor{{0, 1, 0}, -1.0}; // y = -1
    double t = 0.0;
    ASSERT_TRUE(intersectPlane({{0, 1, 0}, {0, -1, 0}}, floor, kInf, t));
    EXPECT_DOUBLE_EQ(t, 2.0);
    EXPECT_FALSE(intersectPlane({{0, 1, 0}, {1, 0, 0}}, floor, kInf, t)) << "parallel";
    EXPECT_FALSE(intersectPlane({{0, 1, 0}, {0, 1, 0}}, floor, kInf, t)) << "behind";
    EXPECT_FALSE(intersectPlane({{0, 1, 0}, {0, -1, 0}}, floor, 1.5, t)) << "beyond tMax";
}

TEST(IntersectPlane, EquationFromScenePlane) {
    Plane plane{{0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0};
    PlaneEquation eq = planeEquation(plane);
    EXPECT_EQ(eq.normal, glm::dvec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(eq.offset, 2.0);
}

bool hitTriangle(const Ray &ray, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, double &t,
                 glm::dvec2 &b12) {
    return intersectTriangle(ray, makeWatertightRay(ray.dir), a, b, c, kInf, t, b12);
}

TEST(IntersectTriangle, HitGivesDistanceAndBarycentrics) {
    double t = 0.0;
    glm::dvec2 b12;
    glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    ASSERT_TRUE(hitTriangle({{0.25, 0.125, 1}, {0, 0, -1}}, a, b, c, t, b12));
    EXPECT_NEAR(t, 1.0, 1e-15);
    EXPECT_NEAR(b12.x, 0.25, 1e-15);
    EXPECT_NEAR(b12.y, 0.125, 1e-15);
    // Back faces are hit too (no culling), with the same barycentrics.
    ASSERT_TRUE(hitTriangle({{0.25, 0.125, -1}, {0, 0, 1}}, a, b, c, t, b12));
    EXPECT_NEAR(t, 1.0, 1e-15);
    EXPECT_NEAR(b12.x, 0.25, 1e-15);
    // An oblique ray.
    glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, -0.2, -1.0));
    glm::dvec3 target = 0.5 * a + 0.2 * b + 0.3 * c;
    ASSERT_TRUE(hitTriangle({target - 2.0 * dir, dir}, a, b, c, t, b12));
    EXPECT_NEAR(t, 2.0, 1e-14);
    EXPECT_NEAR(b12.x, 0.2, 1e-14);
    EXPECT_NEAR(b12.y, 0.3, 1e-14);
}

TEST(IntersectTriangle, Misses) {
    double t = 0.0;
    glm::dvec2 b12;
    glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_FALSE(hitTriangle({{0.6, 0.6, 1}, {0, 0, -1}}, a, b, c, t, b12)) << "outside";
    EXPECT_FALSE(hitTriangle({{0.2, 0.2, 1}, {0, 0, 1}}, a, b, c, t, b12)) << "behind";
    EXPECT_FALSE(hitTriangle({{0.2, 0.2, 1}, {1, 0, 0}}, a, b, c, t, b12)) << "parallel";
    EXPECT_FALSE(intersectTriangle({{0.2, 0.2, 1}, {0, 0, -1}}, makeWatertightRay({0, 0, -1}), a, b,
                                   c, 0.5, t, b12))
        << "beyond tMax";
}

// Watertightness (Woop et al. 2013): rays through the diagonal shared by two triangles of a
// quad, at any angle, hit at least one of them.
TEST(IntersectTriangle, SharedEdgeNeverLeaks) {
    glm::dvec3 p00(0.1, 0.2, 0.3), p10(1.3, 0.1, 0.2), p11(1.2, 1.1, 0.4), p01(0.2, 1.3, 0.1);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int leaks = 0, both = 0;
    for (int i = 0; i < 20000; ++i) {
        double s = 0.01 + 0.98 * unit(rng);
        glm::dvec3 onEdge = p00 + s * (p11 - p00);
        glm::dvec3 dir = glm::normalize(glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, -1.0));
        Ray ray{onEdge - (1.0 + 3.0 * unit(rng)) * dir, dir};
        double t = 0.0;
        glm::dvec2 b12;
        bool first = hitTriangle(ray, p00, p10, p11, t, b12);
        bool second = hitTriangle(ray, p00, p11, p01, t, b12);
        leaks += !first && !second;
        both += first && second;
    }
    EXPECT_EQ(leaks, 0);
    EXPECT_LT(both, 20000) << "the test should not be trivially passed by two big triangles";
}

// Pixel-centre-like rays through exactly representable edge and vertex points.
TEST(IntersectTriangle, ExactEdgeAndVertexPointsHitAtLeastOne) {
    // Four triangles around the vertex (0, 0, 0), edges along the axes and diagonals.
    glm::dvec3 c(0, 0, 0);
    glm::dvec3 ring[4] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    for (double x = -0.75; x <= 0.75; x += 0.25)
        for (double y = -0.75; y <= 0.75; y += 0.25) {
            if (std::abs(x) + std::abs(y) >= 1.0)
                continue;
            Ray ray{{x, y, 2.0}, {0, 0, -1}};
            int hits = 0;
            for (int k = 0; k < 4; ++k) {
                double t = 0.0;
                glm::dvec2 b12;
                hits += hitTriangle(ray, c, ring[k], ring[(k + 1) % 4], t, b12);
            }
            EXPECT_GE(hits, 1) << "at " << x << "," << y;
        }
}

TEST(SceneQuery, ClosestHitAcrossPrimitiveKinds) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.planes.push_back(Plane{{0, 0, -10}, {0, 0, 1}, 0});
    scene.spheres.push_back(Sphere{{0, 0, -5}, 1.0f, 0});
    test::addTriangle(scene, {-1, -1, -2}, {1, -1, -2}, {0, 1, -2}, 0);
    Hit hit;
    ASSERT_TRUE(traceClosest(scene, {{0, 0, 0}, {0, 0, -1}}, kInf, hit));
    EXPECT_EQ(hit.kind, HitKind::Triangle);
    EXPECT_NEAR(hit.t, 2.0, 1e-15);
    // Beside the triangle: the sphere; beside the sphere: the plane.
    ASSERT_TRUE(traceClosest(scene, {{0.8, 0.5, 0}, {0, 0, -1}}, kInf, hit));
    EXPECT_EQ(hit.kind, HitKind::Sphere);
    EXPECT_EQ(hit.index, 0u);
    ASSERT_TRUE(traceClosest(scene, {{3, 3, 0}, {0, 0, -1}}, kInf, hit));
    EXPECT_EQ(hit.kind, HitKind::Plane);
    EXPECT_NEAR(hit.t, 10.0, 1e-15);
    EXPECT_FALSE(traceClosest(scene, {{3, 3, 0}, {0, 0, 1}}, kInf, hit));
    EXPECT_EQ(hit.kind, HitKind::None);
    EXPECT_FALSE(traceClosest(scene, {{3, 3, 0}, {0, 0, -1}}, 9.0, hit)) << "tMax bounds it";
}

TEST(SceneQuery, OccludedOnlyOnTheOpenSegment) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.spheres.push_back(Sphere{{0, 0, -5}, 1.0f, 0});
    Ray ray{{0, 0, 0}, {0, 0, -1}};
    EXPECT_TRUE(traceOccluded(scene, ray, 10.0));
    EXPECT_FALSE(traceOccluded(scene, ray, 3.9)) << "the segment ends before the sphere";
    EXPECT_FALSE(traceOccluded(scene, {{0, 0, 0}, {0, 0, 1}}, 10.0));
    scene.planes.push_back(Plane{{0, 0, 1}, {0, 0, 1}, 0});
    EXPECT_TRUE(traceOccluded(scene, {{0, 0, 0}, {0, 0, 1}}, 10.0));
    test::addTriangle(scene, {-1, -1, -2}, {1, -1, -2}, {0, 1, -2}, 0);
    EXPECT_TRUE(traceOccluded(scene, ray, 2.5));
}

} // namespace
} // namespace prism::reference
