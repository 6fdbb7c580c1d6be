// A scene's extent read back from the cache is the extent sceneExtent finds, box for box; the
// key follows the grid's key and the start-box cap; a damaged entry is found again, never used;
// a prepared scene carries its extent until an instance moves. No device: CPU only.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "accel/grid_cache.h"
#include "cache/blob.h"
#include "cache/disk_cache.h"
#include "render/extent_cache.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"
#include "session/prepared_scene.h"
#include "temp_cache.h"
#include "test_scenes.h"

namespace prism {
namespace {

// The stability scene with a shell of 20,000 small triangles round it: boxes at several block
// sizes, spheres and a plane.
Scene shellScene() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Scene scene = test::stabilityScene();
    for (int i = 0; i < 20'000; ++i) {
        glm::dvec3 c = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng))) * 3.0;
        glm::vec3 p(c);
        test::addTriangle(scene, p, p + glm::vec3(0.02f, 0.0f, 0.0f),
                          p + glm::vec3(0.0f, 0.02f, 0.0f), 0);
    }
    return scene;
}

void expectSameExtent(const SceneExtent &a, const SceneExtent &b) {
    EXPECT_TRUE(test::sameBoxes(a.boxes, b.boxes));
    EXPECT_TRUE(test::sameBoxes(a.startBoxes, b.startBoxes));
    EXPECT_EQ(a.planes, b.planes);
}

using test::CacheInTempDir;

TEST(ExtentCache, ASecondExtentIsReadBackAndEqualsTheFirst) {
    CacheInTempDir c;
    Scene scene = shellScene();
    Grid grid = buildGrid(scene);
    std::string gridKey = gridCacheKey(scene, GridOptions{});
    SceneExtent found = sceneExtent(scene, grid);
    ASSERT_GT(found.boxes.size(), 100u);
    ASSERT_GT(found.startBoxes.size(), found.boxes.size());
    ASSERT_EQ(found.planes.size(), 1u);

    ExtentCacheOutcome first, second;
    SceneExtent stored = sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, gridKey, &first);
    SceneExtent read = sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, gridKey, &second);
    EXPECT_EQ(first.state, "miss");
    EXPECT_EQ(second.state, "hit");
    expectSameExtent(stored, found);
    expectSameExtent(read, found);
    EXPECT_TRUE(c.warnings.empty());

    ExtentCacheOutcome off, noKey;
    expectSameExtent(sceneExtentCached(scene, grid, kMaxStartBoxes, nullptr, gridKey, &off), found);
    expectSameExtent(sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, "", &noKey), found);
    EXPECT_EQ(off.state, "off");
    EXPECT_EQ(noKey.state, "off");
}

// The cap decides the start blocks, so an extent kept for one cap is not handed to another.
TEST(ExtentCache, KeyFollowsTheGridKeyAndTheStartBoxCap) {
    const std::string base = extentCacheKey("grid-a", kMaxStartBoxes);
    EXPECT_EQ(base.size(), 32u);
    EXPECT_EQ(extentCacheKey("grid-a", kMaxStartBoxes), base);
    EXPECT_NE(extentCacheKey("grid-b", kMaxStartBoxes), base);
    EXPECT_NE(extentCacheKey("grid-a", 64), base);

    CacheInTempDir c;
    Scene scene = shellScene();
    Grid grid = buildGrid(scene);
    std::string gridKey = gridCacheKey(scene, GridOptions{});
    sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, gridKey);
    ExtentCacheOutcome fewer;
    SceneExtent capped = sceneExtentCached(scene, grid, 64, &c.cache, gridKey, &fewer);
    EXPECT_EQ(fewer.state, "miss");
    expectSameExtent(capped, sceneExtent(scene, grid, 64));
    EXPECT_LT(capped.startBoxes.size(), sceneExtent(scene, grid).startBoxes.size());
}

TEST(ExtentCache, PackedExtentsUnpackToTheSameBoxes) {
    Scene scene = shellScene();
    Grid grid = buildGrid(scene);
    SceneExtent found = sceneExtent(scene, grid);
    expectSameExtent(unpackExtent(packExtent(found)), found);
    std::string bytes = packExtent(found);
    EXPECT_THROW(unpackExtent(std::string_view(bytes).substr(0, bytes.size() - 8)),
                 BlobFormatError);
    EXPECT_THROW(unpackExtent(bytes + "x"), BlobFormatError);
    SceneExtent nan = found;
    nan.boxes[3].max.y = std::nan("");
    EXPECT_THROW(unpackExtent(packExtent(nan)), BlobFormatError);
}

// An entry whose bytes pass the cache's checks but are no extent, and one whose bytes were
// changed on disk: each is removed with a warning and the extent found again.
TEST(ExtentCache, ADamagedEntryIsFoundAgain) {
    Scene scene = shellScene();
    Grid grid = buildGrid(scene);
    std::string gridKey = gridCacheKey(scene, GridOptions{});
    SceneExtent found = sceneExtent(scene, grid);
    std::string key = extentCacheKey(gridKey, kMaxStartBoxes);
    {
        CacheInTempDir c;
        c.cache.store("extent", key, kExtentCacheFormat, "not an extent");
        ExtentCacheOutcome outcome;
        expectSameExtent(
            sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, gridKey, &outcome), found);
        EXPECT_EQ(outcome.state, "miss");
        ASSERT_EQ(c.warnings.size(), 1u);
        ExtentCacheOutcome again;
        sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, gridKey, &again);
        EXPECT_EQ(again.state, "hit") << "the extent found again was stored";
    }
    {
        CacheInTempDir c;
        sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, gridKey);
        std::filesystem::path entry = c.cache.entryPath("extent", key);
        ASSERT_TRUE(std::filesystem::exists(entry));
        std::fstream file(entry, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(-20, std::ios::end);
        file.put('\x5a');
        file.close();
        ExtentCacheOutcome outcome;
        expectSameExtent(
            sceneExtentCached(scene, grid, kMaxStartBoxes, &c.cache, gridKey, &outcome), found);
        EXPECT_EQ(outcome.state, "miss");
        EXPECT_EQ(c.warnings.size(), 1u);
    }
}

// prepareScene finds the extent of the scene and grid it made, cached or not, and drops it when
// an instance moves (the tracer's setScene finds the moved scene's).
TEST(ExtentCache, APreparedSceneCarriesItsExtentUntilAnInstanceMoves) {
    CacheInTempDir c;
    for (const DiskCache *cache : std::vector<const DiskCache *>{nullptr, &c.cache}) {
        PreparedScene prepared = prepareScene(shellScene(), GridOptions{}, cache);
        ASSERT_TRUE(prepared.extent.has_value());
        expectSameExtent(*prepared.extent, sceneExtent(prepared.scene, prepared.grid));
        EXPECT_EQ(prepared.extentCache.state, cache ? "miss" : "off");
    }
    PreparedScene again = prepareScene(shellScene(), GridOptions{}, &c.cache);
    EXPECT_EQ(again.extentCache.state, "hit");

    PreparedScene animated =
        prepareScene(loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "moving-instances.scene"),
                     GridOptions{GridOptions::Mode::Regular}, nullptr);
    ASSERT_TRUE(animated.extent.has_value());
    EXPECT_FALSE(moveToFrame(animated, 1.0));
    EXPECT_TRUE(animated.extent.has_value()) << "nothing moved: the extent holds";
    ASSERT_TRUE(moveToFrame(animated, 13.0));
    EXPECT_FALSE(animated.extent.has_value());
}

} // namespace
} // namespace prism
