// Primitive/box overlap: exact cases, and no false negatives against dense point sampling.
#include <random>

#include <gtest/gtest.h>

#include "accel/overlap_tests.h"

namespace prism {
namespace {

const glm::dvec3 kLo(0.0), kHi(1.0);

TEST(SphereOverlapsBox, InsideTouchingAndOutsideTheCorner) {
    EXPECT_TRUE(sphereOverlapsBox({0.5, 0.5, 0.5}, 0.1, kLo, kHi));
    EXPECT_TRUE(sphereOverlapsBox({2.0, 0.5, 0.5}, 1.0, kLo, kHi)); // touches a face
    // Bounding boxes overlap, but the sphere is beyond the corner (distance sqrt(3) * 0.5).
    EXPECT_FALSE(sphereOverlapsBox({1.5, 1.5, 1.5}, 0.8, kLo, kHi));
    EXPECT_TRUE(sphereOverlapsBox({1.5, 1.5, 1.5}, 0.9, kLo, kHi));
}

TEST(TriangleOverlapsBox, InsideCrossingAndAlongTheBoxBoundingBox) {
    EXPECT_TRUE(triangleOverlapsBox({0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.8, 0.5}, kLo, kHi));
    // A huge triangle whose interior cuts through the box though no vertex is near it.
    EXPECT_TRUE(triangleOverlapsBox({-10, -10, 0.5}, {10, -10, 0.5}, {0, 10, 0.5}, kLo, kHi));
    // Plane and bounding box both cut the box, but the triangle lies beyond the box's
    // (1, 1) edge: only the edge x box-axis cross product separates them.
    EXPECT_FALSE(
        triangleOverlapsBox({2.6, -0.5, 0.5}, {-0.5, 2.6, 0.5}, {2.6, 2.6, 0.5}, kLo, kHi));
    EXPECT_TRUE(triangleOverlapsBox({1.9, -0.5, 0.5}, {-0.5, 1.9, 0.5}, {1.9, 1.9, 0.5}, kLo, kHi));
    // Bounding box overlaps, but the tilted plane passes beyond the box's far corner.
    EXPECT_FALSE(triangleOverlapsBox({3.5, 0, 0}, {0, 3.5, 0}, {0, 0, 3.5}, kLo, kHi));
    EXPECT_TRUE(triangleOverlapsBox({2.5, 0, 0}, {0, 2.5, 0}, {0, 0, 2.5}, kLo, kHi));
}

// A vertex on the box's boundary (a face, an edge, a corner) touches the box: the closed box
// overlaps, whatever the rest of the triangle does. The test settles this case first.
TEST(TriangleOverlapsBox, AVertexOnTheBoundaryTouches) {
    const glm::dvec3 far1(5.0, 7.0, -4.0), far2(6.0, -3.0, 8.0);
    for (const glm::dvec3 &v : {glm::dvec3(1.0, 0.5, 0.5), glm::dvec3(0.0, 1.0, 0.3),
                                glm::dvec3(1.0, 1.0, 1.0), glm::dvec3(0.0, 0.0, 0.0)}) {
        EXPECT_TRUE(triangleOverlapsBox(v, far1, far2, kLo, kHi));
        EXPECT_TRUE(triangleOverlapsBox(far1, v, far2, kLo, kHi));
        EXPECT_TRUE(triangleOverlapsBox(far1, far2, v, kLo, kHi));
    }
    // Just outside the same points, with the rest of the triangle leaning away: no overlap.
    EXPECT_FALSE(
        triangleOverlapsBox({1.0 + 1e-9, 0.5, 0.5}, {3.0, 0.5, 0.5}, {3.0, 0.6, 0.5}, kLo, kHi));
    EXPECT_FALSE(
        triangleOverlapsBox({-1e-9, -1e-9, -1e-9}, {-1.0, -2.0, 0.0}, {-2.0, 0.0, -1.0}, kLo, kHi));
}

// Sample points densely over random triangles: wherever a sample lies inside the box, the
// test must say they overlap (a false negative would drop a primitive from a cell).
TEST(TriangleOverlapsBox, NoFalseNegativesOnRandomTriangles) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1.0, 2.0);
    int overlapping = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        glm::dvec3 p[3];
        for (glm::dvec3 &v : p)
            v = {coord(rng), coord(rng), coord(rng)};
        bool sampledInside = false;
        const int n = 40;
        for (int i = 0; i <= n && !sampledInside; ++i)
            for (int j = 0; i + j <= n && !sampledInside; ++j) {
                double b1 = double(i) / n, b2 = double(j) / n;
                glm::dvec3 q = (1 - b1 - b2) * p[0] + b1 * p[1] + b2 * p[2];
                sampledInside =
                    glm::all(glm::greaterThanEqual(q, kLo)) && glm::all(glm::lessThanEqual(q, kHi));
            }
        bool overlaps = triangleOverlapsBox(p[0], p[1], p[2], kLo, kHi);
        if (sampledInside) {
            ++overlapping;
            EXPECT_TRUE(overlaps) << "trial " << trial;
        }
    }
    EXPECT_GT(overlapping, 200); // the sampling did exercise the positive case
}

// The other direction, by distances: a triangle reported as overlapping must come within a
// tiny distance of the box (checked by sampling the triangle very finely for near misses is
// costly; instead check that far-away triangles are rejected).
TEST(TriangleOverlapsBox, RejectsTrianglesOutsideAnEnlargedBox) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coord(-3.0, 4.0);
    int rejected = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        glm::dvec3 p[3];
        for (glm::dvec3 &v : p)
            v = {coord(rng), coord(rng), coord(rng)};
        if (!triangleOverlapsBox(p[0], p[1], p[2], kLo, kHi)) {
            ++rejected;
            continue;
        }
        // An overlapping triangle has a point within the box: find one by sampling finely and
        // allow the sampling's spacing as distance.
        double best = 1e9;
        const int n = 200;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                double b1 = double(i) / n, b2 = double(j) / n;
                glm::dvec3 q = (1 - b1 - b2) * p[0] + b1 * p[1] + b2 * p[2];
                glm::dvec3 d = q - glm::clamp(q, kLo, kHi);
                best = std::min(best, glm::length(d));
            }
        double spacing = std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]),
                                   glm::length(p[0] - p[2])}) /
                         n;
        EXPECT_LE(best, spacing) << "trial " << trial;
    }
    EXPECT_GT(rejected, 200);
}

} // namespace
} // namespace prism
