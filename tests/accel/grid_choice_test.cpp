// `--grid auto` picks the regular grid or the adaptive one by the tracer's work on the camera's
// rays, counted on the CPU (accel/grid_choice.h, accel/walk_counts.h).
#include <gtest/gtest.h>

#include "accel/grid.h"
#include "accel/grid_choice.h"
#include "accel/walk_counts.h"
#include "grid_test_scenes.h"

namespace prism {
namespace {

// Spheres spread evenly in front of the camera: one regular grid suits them.
Scene evenSpheres() {
    Scene scene = test::randomSpheresAndTriangles(31, 400, 0);
    scene.camera.eye = {0.0f, 0.0f, 30.0f};
    return scene;
}

// A dense cluster in a large room, the camera close to the cluster: one grid fails there.
Scene clusterSeenFromClose() {
    Scene scene = test::clusterInARoom(51, 3000, 60);
    scene.camera.eye = {0.0f, 0.5f, -4.0f};
    scene.camera.look = {0.0f, 0.0f, 0.0f};
    return scene;
}

TEST(WalkCounts, CountWhatTheWalkTests) {
    Scene scene = clusterSeenFromClose();
    Grid off = buildGrid(scene, parseGridOption("off"));
    WalkCounts brute = countWalks(scene, off, 4.0 / 3.0, 16);
    // One cell holding everything: every ray that enters it tests every primitive.
    EXPECT_EQ(brute.rays, 16u * 12u);
    EXPECT_LE(brute.cellsPerRay, 1.0);
    EXPECT_NEAR(brute.testsPerRay, brute.cellsPerRay * double(scene.finitePrimitiveCount()), 1e-9);
    WalkCounts adaptive =
        countWalks(scene, buildGrid(scene, parseGridOption("adaptive")), 4.0 / 3.0, 16);
    EXPECT_LT(adaptive.testsPerRay, brute.testsPerRay / 20.0);
}

// Counting that stops early gives lower bounds, which is all the choice needs from a grid that
// crowds the camera's rays (and counting such a grid in full takes seconds).
TEST(WalkCounts, StoppingEarlyGivesLowerBounds) {
    Scene scene = clusterSeenFromClose();
    Grid off = buildGrid(scene, parseGridOption("off"));
    WalkCounts full = countWalks(scene, off, 4.0 / 3.0, 16);
    WalkCounts stopped = countWalks(scene, off, 4.0 / 3.0, 16, 100.0);
    EXPECT_FALSE(full.stopped);
    EXPECT_TRUE(stopped.stopped);
    EXPECT_LT(stopped.rays, full.rays);
    EXPECT_GT(stopped.testsPerRay, 100.0);
    EXPECT_LE(stopped.testsPerRay, full.testsPerRay);
    EXPECT_LE(stopped.cellsPerRay, full.cellsPerRay);
}

// A regular grid priced without its cells: each ray crosses at least the cells up to its
// nearest hit (found through another grid) and tests at least what it hits.
TEST(WalkCounts, LowerBoundsPriceAGridNotBuilt) {
    for (const Scene &scene : {clusterSeenFromClose(), evenSpheres()}) {
        WalkCounts adaptive =
            countWalks(scene, buildGrid(scene, parseGridOption("adaptive")), 4.0 / 3.0, 24);
        ASSERT_EQ(adaptive.nearestHits.size(), 24u * 18u);
        Grid regular = buildGrid(scene, parseGridOption("regular"));
        WalkCounts exact = countWalks(scene, regular, 4.0 / 3.0, 24);
        EXPECT_EQ(exact.nearestHits, adaptive.nearestHits) << "the same hits through any grid";
        Grid layout = regular;
        layout.cellStart.clear();
        layout.cellPrimitives.clear();
        WalkCounts bound = lowerBoundWalks(scene, layout, 4.0 / 3.0, 24, adaptive.nearestHits);
        EXPECT_TRUE(bound.stopped);
        EXPECT_LE(bound.cellsPerRay, exact.cellsPerRay);
        EXPECT_GT(bound.cellsPerRay, 0.5 * exact.cellsPerRay) << "and not far below";
        EXPECT_LE(bound.testsPerRay, exact.testsPerRay);
        EXPECT_GT(bound.testsPerRay, 0.0);
    }
}

// From kAdaptiveFirstFrom primitives the adaptive grid comes first, and where the regular
// grid's lower bounds settle the choice, the regular grid is not built: the same choice.
TEST(GridChoice, ABigClusterIsChosenAdaptiveWithoutTheRegularGrid) {
    Scene scene = test::clusterInARoom(52, int(kAdaptiveFirstFrom), 0);
    scene.camera.eye = {0.0f, 0.5f, -4.0f};
    scene.camera.look = {0.0f, 0.0f, 0.0f};
    Grid g = buildGrid(scene);
    EXPECT_TRUE(g.adaptive()) << g.choice;
    EXPECT_EQ(g.choice.rfind("adaptive", 0), 0u) << g.choice;
    EXPECT_NE(g.choice.find("(not built)"), std::string::npos) << g.choice;
    Grid adaptive = buildGrid(scene, parseGridOption("adaptive"));
    EXPECT_EQ(g.entries, adaptive.entries);
    EXPECT_EQ(g.cellPrimitives, adaptive.cellPrimitives);
    // The regular grid's own counts: above its bounds, and the choice would be the same.
    Grid regular = buildGrid(scene, parseGridOption("regular"));
    WalkCounts counts = countWalks(scene, regular, 4.0 / 3.0, 48, 200.0);
    WalkCounts mine = countWalks(scene, adaptive, 4.0 / 3.0, 48);
    EXPECT_LT(mine.testsPerRay + 3.0 * mine.cellsPerRay,
              kAdaptiveMargin * (counts.testsPerRay + counts.cellsPerRay));
}

TEST(GridChoice, EvenScenesKeepTheRegularGrid) {
    Scene scene = evenSpheres();
    Grid g = buildGrid(scene);
    EXPECT_FALSE(g.adaptive()) << g.choice;
    EXPECT_EQ(g.choice.rfind("regular", 0), 0u) << g.choice;
    Grid regular = buildGrid(scene, parseGridOption("regular"));
    EXPECT_EQ(g.cellPrimitives, regular.cellPrimitives) << "the very grid --grid regular builds";
}

TEST(GridChoice, AClusterInARoomGetsTheAdaptiveGrid) {
    Scene scene = clusterSeenFromClose();
    Grid g = buildGrid(scene);
    EXPECT_TRUE(g.adaptive()) << g.choice;
    EXPECT_EQ(g.choice.rfind("adaptive", 0), 0u) << g.choice;
    Grid adaptive = buildGrid(scene, parseGridOption("adaptive"));
    EXPECT_EQ(g.cellPrimitives, adaptive.cellPrimitives);
    EXPECT_EQ(g.entries, adaptive.entries);
}

TEST(GridChoice, AnEmptySceneIsARegularGrid) {
    Scene scene;
    Grid g = buildGrid(scene);
    EXPECT_FALSE(g.adaptive());
    EXPECT_TRUE(g.cellPrimitives.empty());
}

TEST(GridChoice, OnlyAutoChooses) {
    Scene scene = clusterSeenFromClose();
    EXPECT_FALSE(buildGrid(scene, parseGridOption("regular")).adaptive());
    EXPECT_TRUE(buildGrid(scene, parseGridOption("regular")).choice.empty());
    EXPECT_EQ(parseGridOption("regular").mode, GridOptions::Mode::Regular);
}

} // namespace
} // namespace prism
