// A grid read back from the cache is the grid the builder makes, array for array; the key
// follows what the build reads (positions, options, the camera for --grid auto) and nothing
// else (materials); a damaged entry is rebuilt, never used.
#include <gtest/gtest.h>

#include <fstream>

#include "accel/grid_cache.h"
#include "cache/blob.h"
#include "cache/disk_cache.h"
#include "grid_test_scenes.h"
#include "temp_cache.h"

namespace prism {
namespace {

// A cluster in a room, and two placed copies of a small mesh (a second grid level).
Scene sceneWithInstances() {
    Scene scene = test::clusterInARoom(51, 600, 40);
    Scene mesh = test::randomSpheresAndTriangles(52, 0, 200, 1.0);
    scene.prototypes.push_back(MeshPrototype{"m", mesh.triangles, mesh.triangleShading});
    for (int k = 0; k < 2; ++k) {
        Instance i;
        i.translation = glm::dvec3(30.0 * k - 15.0, 5.0, 0.0);
        i.scale = 1.5;
        scene.instances.push_back(i);
    }
    return scene;
}

using test::CacheInTempDir;

TEST(GridCache, PackedGridsUnpackToTheSameArrays) {
    Scene scene = sceneWithInstances();
    for (GridOptions::Mode mode : {GridOptions::Mode::Regular, GridOptions::Mode::Adaptive,
                                   GridOptions::Mode::Auto, GridOptions::Mode::Off}) {
        Grid built = buildGrid(scene, GridOptions{mode});
        ASSERT_EQ(built.meshGrids.size(), 1u);
        test::expectSameGrid(unpackGrid(packGrid(built)), built);
    }
    GridOptions lean{GridOptions::Mode::Adaptive};
    lean.effort = GridOptions::Effort::Lean;
    Grid built = buildGrid(scene, lean);
    ASSERT_TRUE(built.lean);
    test::expectSameGrid(unpackGrid(packGrid(built)), built);
}

TEST(GridCache, SecondBuildIsReadBackAndEqualsTheFirst) {
    CacheInTempDir c;
    Scene scene = sceneWithInstances();
    for (GridOptions::Mode mode : {GridOptions::Mode::Adaptive, GridOptions::Mode::Auto}) {
        GridOptions options{mode};
        Grid cold = buildGrid(scene, options);
        GridCacheOutcome first, second;
        Grid stored = buildGridCached(scene, options, {&c.cache}, &first);
        Grid read = buildGridCached(scene, options, {&c.cache}, &second);
        EXPECT_EQ(first.state, "miss");
        EXPECT_EQ(second.state, "hit");
        EXPECT_EQ(first.key, second.key);
        test::expectSameGrid(stored, cold);
        test::expectSameGrid(read, cold);
    }
    EXPECT_TRUE(c.warnings.empty());
    GridCacheOutcome off;
    buildGridCached(scene, GridOptions{}, {nullptr}, &off);
    EXPECT_EQ(off.state, "off");
}

TEST(GridCache, KeyFollowsWhatTheBuildReads) {
    Scene scene = sceneWithInstances();
    const GridOptions adaptive{GridOptions::Mode::Adaptive}, autoGrid{GridOptions::Mode::Auto};
    const std::string base = gridCacheKey(scene, adaptive);
    EXPECT_EQ(base.size(), 32u);
    EXPECT_EQ(gridCacheKey(scene, adaptive), base) << "the same scene, the same key";

    auto changed = [&](const std::function<void(Scene &)> &edit, const GridOptions &options) {
        Scene copy = scene;
        edit(copy);
        return gridCacheKey(copy, options);
    };
    EXPECT_NE(changed([](Scene &s) { s.triangles[7].p[1].x += 1e-9; }, adaptive), base);
    EXPECT_NE(changed([](Scene &s) { s.triangles.pop_back(); }, adaptive), base);
    EXPECT_NE(changed([](Scene &s) { s.spheres[3].radius *= 1.001f; }, adaptive), base);
    EXPECT_NE(changed([](Scene &s) { s.prototypes[0].triangles[0].p[0].z += 0.5; }, adaptive),
              base);
    EXPECT_NE(changed([](Scene &s) { s.instances[1].translation.y += 1.0; }, adaptive), base);
    EXPECT_NE(changed([](Scene &s) { s.instances[1].scale = 2.0; }, adaptive), base);
    EXPECT_NE(gridCacheKey(scene, GridOptions{GridOptions::Mode::Regular}), base);
    GridOptions denser{GridOptions::Mode::Regular};
    denser.density = 8.0f;
    EXPECT_NE(gridCacheKey(scene, denser),
              gridCacheKey(scene, GridOptions{GridOptions::Mode::Regular}));
    // The effort as decided keys the entry, not the samples it was decided by.
    GridOptions oneImage = adaptive, otherImage = adaptive, lean = adaptive;
    oneImage.cameraSamples = 2; // fewer than 4 a primitive
    otherImage.cameraSamples = 1;
    ASSERT_TRUE(buildsLean(oneImage, scene.finitePrimitiveCount()));
    EXPECT_NE(gridCacheKey(scene, oneImage), base);
    EXPECT_EQ(gridCacheKey(scene, otherImage), gridCacheKey(scene, oneImage));
    lean.effort = GridOptions::Effort::Lean;
    EXPECT_EQ(gridCacheKey(scene, lean), gridCacheKey(scene, oneImage));
    GridOptions manyImages = oneImage;
    manyImages.cameraSamples = 1u << 30;
    EXPECT_EQ(gridCacheKey(scene, manyImages), base);
    // Not read by the build: materials and normals; the camera only where auto counts rays.
    EXPECT_EQ(changed([](Scene &s) { s.triangles[7].material = 3; }, adaptive), base);
    EXPECT_EQ(changed(
                  [](Scene &s) {
                      shadingFor(s.triangles[7], s.triangleShading).n[0] = glm::vec3(1, 0, 0);
                  },
                  adaptive),
              base);
    EXPECT_EQ(changed([](Scene &s) { s.lights.push_back(Light{}); }, adaptive), base);
    EXPECT_EQ(changed([](Scene &s) { s.camera.look.x += 1.0; }, adaptive), base);
    EXPECT_NE(changed([](Scene &s) { s.camera.look.x += 1.0; }, autoGrid),
              gridCacheKey(scene, autoGrid));
}

// The mesh grids' key follows the prototypes' positions alone, so a viewer's reload that moves
// instances (or the origin) keeps them; a grid built over kept mesh grids is the grid built anew.
TEST(GridCache, MeshGridsKeyAndGridOverKeptMeshGrids) {
    Scene scene = sceneWithInstances();
    const std::string key = meshGridsKey(scene);
    Scene moved = scene;
    moved.instances[1].translation.x += 2.0;
    moved.spheres[0].center.y += 1.0f;
    moved.instances[0].material = 2;
    EXPECT_EQ(meshGridsKey(moved), key);
    Scene edited = scene;
    edited.prototypes[0].triangles[3].p[2].y += 1e-9;
    EXPECT_NE(meshGridsKey(edited), key);
    edited = scene;
    edited.prototypes.push_back(edited.prototypes[0]);
    EXPECT_NE(meshGridsKey(edited), key);
    EXPECT_EQ(meshGridsKey(Scene{}), "") << "no prototypes, no mesh key";
    // The grid's key holds the mesh key: given or digested, the same; another, another key.
    EXPECT_EQ(gridCacheKey(scene, GridOptions{}, key), gridCacheKey(scene, GridOptions{}));
    EXPECT_NE(gridCacheKey(scene, GridOptions{}, meshGridsKey(edited)),
              gridCacheKey(scene, GridOptions{}));
    EXPECT_NE(gridCacheKey(edited, GridOptions{}), gridCacheKey(scene, GridOptions{}));

    for (GridOptions::Mode mode :
         {GridOptions::Mode::Auto, GridOptions::Mode::Adaptive, GridOptions::Mode::Regular}) {
        SCOPED_TRACE(int(mode));
        Grid first = buildGrid(scene, GridOptions{mode});
        test::expectSameGrid(buildGridOverMeshGrids(moved, GridOptions{mode}, first.meshGrids),
                             buildGrid(moved, GridOptions{mode}));
    }
    EXPECT_THROW(buildGridOverMeshGrids(scene, GridOptions{}, {}), Error);
}

// An entry whose bytes pass the checksum but do not make a grid (a writer's bug, or a
// format change without a new version) is removed and the grid built anew.
TEST(GridCache, AnEntryThatIsNoGridIsRebuilt) {
    CacheInTempDir c;
    Scene scene = test::clusterInARoom(53, 300, 20);
    GridOptions options{GridOptions::Mode::Adaptive};
    std::string key = gridCacheKey(scene, options);
    std::string packed = packGrid(buildGrid(scene, options));
    c.cache.store("grid", key, kGridCacheFormat, packed.substr(0, packed.size() / 2));
    GridCacheOutcome outcome;
    Grid grid = buildGridCached(scene, options, {&c.cache}, &outcome);
    EXPECT_EQ(outcome.state, "miss");
    ASSERT_EQ(c.warnings.size(), 1u);
    EXPECT_NE(c.warnings[0].find("damaged"), std::string::npos) << c.warnings[0];
    test::expectSameGrid(grid, buildGrid(scene, options));
    // The rebuilt grid was stored whole in its place.
    GridCacheOutcome again;
    test::expectSameGrid(buildGridCached(scene, options, {&c.cache}, &again), grid);
    EXPECT_EQ(again.state, "hit");
    EXPECT_THROW(unpackGrid(packed + "x"), BlobFormatError);
    EXPECT_THROW(unpackGrid(""), BlobFormatError);
}

} // namespace
} // namespace prism
