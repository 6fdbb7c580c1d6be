// Choosing the resolution: cells ~ density * primitives, aspect following the bounds.
#include <gtest/gtest.h>

#include "accel/grid_resolution.h"

namespace prism {
namespace {

int cells(glm::ivec3 r) {
    return r.x * r.y * r.z;
}

TEST(GridResolution, CubeGetsCubicCellsNearTheTarget) {
    glm::ivec3 r = chooseResolution(glm::dvec3(2.0), 1000, 2.0);
    EXPECT_EQ(r.x, r.y);
    EXPECT_EQ(r.y, r.z);
    EXPECT_NEAR(cells(r), 2000, 2000 * 0.3);
}

TEST(GridResolution, AspectFollowsTheBounds) {
    glm::ivec3 r = chooseResolution(glm::dvec3(8.0, 2.0, 1.0), 4000, 2.0);
    EXPECT_NEAR(double(r.x) / r.y, 4.0, 0.5);
    EXPECT_NEAR(double(r.y) / r.z, 2.0, 0.5);
}

TEST(GridResolution, FlatSceneGetsOneCellAcrossItsThinAxis) {
    glm::ivec3 r = chooseResolution(glm::dvec3(10.0, 10.0, 1e-4), 5000, 2.0);
    EXPECT_EQ(r.z, 1);
    EXPECT_EQ(r.x, r.y);
    EXPECT_NEAR(cells(r), 10000, 10000 * 0.3);
}

TEST(GridResolution, LineOfPrimitivesGetsA1DGrid) {
    glm::ivec3 r = chooseResolution(glm::dvec3(100.0, 0.01, 0.01), 50, 2.0);
    EXPECT_EQ(r, glm::ivec3(100, 1, 1));
}

TEST(GridResolution, FewPrimitivesFewCellsAndClampedAxes) {
    EXPECT_EQ(chooseResolution(glm::dvec3(1.0), 0, 2.0), glm::ivec3(1));
    EXPECT_EQ(chooseResolution(glm::dvec3(1.0), 1, 1.0), glm::ivec3(1));
    glm::ivec3 huge = chooseResolution(glm::dvec3(1.0), 100000000, 8.0);
    EXPECT_LE(huge.x, 256);
    EXPECT_LE(uint64_t(cells(huge)), kMaxGridCells);
}

} // namespace
} // namespace prism
