// Building the grid: bounds, CSR layout, and primitives only in the cells they overlap.
#include <gtest/gtest.h>

#include "accel/bounds.h"
#include "accel/grid.h"
#include "accel/overlap_tests.h"
#include "grid_test_scenes.h"
#include "scene/primitive_ids.h"

namespace prism {
namespace {

void expectWellFormed(const Grid &g) {
    ASSERT_EQ(g.cellStart.size(), g.cellCount() + 1);
    EXPECT_EQ(g.cellStart.front(), 0u);
    EXPECT_EQ(g.cellStart.back(), g.cellPrimitives.size());
    for (size_t i = 0; i + 1 < g.cellStart.size(); ++i)
        ASSERT_LE(g.cellStart[i], g.cellStart[i + 1]);
    for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(g.cellSize[a] * g.resolution[a], g.boundsMax[a] - g.boundsMin[a],
                    1e-5 * (g.boundsMax[a] - g.boundsMin[a]));
}

std::vector<uint32_t> primitivesOf(const Grid &g, glm::ivec3 cell) {
    uint32_t i = g.cellIndex(cell);
    return {g.cellPrimitives.begin() + g.cellStart[i],
            g.cellPrimitives.begin() + g.cellStart[i + 1]};
}

TEST(GridBuilder, EmptySceneIsOneEmptyCell) {
    Scene scene;
    scene.planes.push_back(Plane{});
    Grid g = buildGrid(scene);
    expectWellFormed(g);
    EXPECT_EQ(g.resolution, glm::ivec3(1));
    EXPECT_TRUE(g.cellPrimitives.empty());
}

TEST(GridBuilder, BoundsCoverFinitePrimitivesOnlyAndAreTight) {
    Scene scene;
    scene.planes.push_back(Plane{}); // infinite: not in the grid
    scene.spheres.push_back(Sphere{{1, 2, 3}, 0.5f, 0});
    Triangle t;
    t.p[0] = {-4, 0, 0};
    t.p[1] = {-3, 0, 0};
    t.p[2] = {-4, 1, 0};
    scene.triangles.push_back(t);
    Grid g = buildGrid(scene);
    expectWellFormed(g);
    glm::vec3 lo(-4.0f, 0.0f, 0.0f), hi(1.5f, 2.5f, 3.5f);
    for (int a = 0; a < 3; ++a) {
        EXPECT_LT(g.boundsMin[a], lo[a]);
        EXPECT_GT(g.boundsMin[a], lo[a] - 0.01f);
        EXPECT_GT(g.boundsMax[a], hi[a]);
        EXPECT_LT(g.boundsMax[a], hi[a] + 0.01f);
    }
}

TEST(GridBuilder, OffPutsEveryPrimitiveInOneCell) {
    Scene scene = test::randomSpheresAndTriangles(1, 30, 40);
    Grid g = buildGrid(scene, parseGridOption("off"));
    expectWellFormed(g);
    EXPECT_EQ(g.resolution, glm::ivec3(1));
    ASSERT_EQ(g.cellPrimitives.size(), 70u);
    for (uint32_t i = 0; i < 70; ++i)
        EXPECT_EQ(g.cellPrimitives[i], i);
    EXPECT_EQ(g.maxPerCell, 70u);
}

TEST(GridBuilder, FixedResolutionIsKept) {
    Scene scene = test::randomSpheresAndTriangles(2, 10, 10);
    Grid g = buildGrid(scene, parseGridOption("3x5x7"));
    expectWellFormed(g);
    EXPECT_EQ(g.resolution, glm::ivec3(3, 5, 7));
}

TEST(GridBuilder, AutoResolutionGrowsWithThePrimitiveCount) {
    Grid small = buildGrid(test::randomSpheresAndTriangles(3, 20, 0));
    Grid large = buildGrid(test::randomSpheresAndTriangles(3, 2000, 0));
    EXPECT_LT(small.cellCount() * 20, large.cellCount());
    double target = GridOptions{}.density * 2000;
    EXPECT_NEAR(double(large.cellCount()), target, 0.3 * target);
}

// A long, thin diagonal triangle: its bounding box covers a 10x10 slab of cells, but it only
// crosses the diagonal ones. Bounding-box binning would list it in all 100.
TEST(GridBuilder, TriangleOnlyInCellsItOverlaps) {
    Scene scene;
    Triangle t;
    t.p[0] = {0.0f, 0.0f, 0.5f};
    t.p[1] = {10.0f, 10.0f, 0.5f};
    t.p[2] = {10.0f, 10.0f, 0.6f};
    scene.triangles.push_back(t);
    scene.spheres.push_back(Sphere{{0, 0, 0}, 0.01f, 0}); // stretch the bounds to a 10^3 box
    scene.spheres.push_back(Sphere{{10, 10, 10}, 0.01f, 0});
    Grid g = buildGrid(scene, parseGridOption("10"));
    expectWellFormed(g);
    int cellsWithTriangle = 0;
    for (int z = 0; z < 10; ++z)
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 10; ++x)
                for (uint32_t id : primitivesOf(g, {x, y, z}))
                    if (id == 2) {
                        ++cellsWithTriangle;
                        EXPECT_EQ(z, 0);
                        EXPECT_LE(std::abs(x - y), 1) << x << "," << y;
                    }
    EXPECT_GE(cellsWithTriangle, 10);
    EXPECT_LE(cellsWithTriangle, 30);
}

// Each primitive is listed in exactly the cells it overlaps, give or take the thin slack
// around each cell: every overlapped cell lists it, and a listed cell is within a whisker.
TEST(GridBuilder, CellsListExactlyTheOverlappingPrimitives) {
    Scene scene = test::randomSpheresAndTriangles(5, 150, 300);
    Grid g = buildGrid(scene, parseGridOption("12x9x10"));
    expectWellFormed(g);
    for (int z = 0; z < g.resolution.z; ++z)
        for (int y = 0; y < g.resolution.y; ++y)
            for (int x = 0; x < g.resolution.x; ++x) {
                glm::dvec3 lo =
                    glm::dvec3(g.boundsMin) + glm::dvec3(x, y, z) * glm::dvec3(g.cellSize);
                test::expectCellListsExactly(scene, lo, lo + glm::dvec3(g.cellSize),
                                             primitivesOf(g, {x, y, z}));
                if (HasFatalFailure())
                    return;
            }
}

TEST(GridBuilder, MaxPerCellIsTheFullestCell) {
    Scene scene = test::randomSpheresAndTriangles(6, 100, 0);
    Grid g = buildGrid(scene, parseGridOption("8"));
    uint32_t maxCount = 0;
    for (size_t i = 0; i + 1 < g.cellStart.size(); ++i)
        maxCount = std::max(maxCount, g.cellStart[i + 1] - g.cellStart[i]);
    EXPECT_EQ(g.maxPerCell, maxCount);
    EXPECT_GT(maxCount, 1u);
}

} // namespace
} // namespace prism
