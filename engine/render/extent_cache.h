#pragma once
// Scene extents (render/traced_tiles.h, sceneExtent) kept in the disk cache beside the grid
// they were found over: finding them is a pass of exact surface-box tests over every primitive
// at two or three block sizes, 60-70 ms of a warm 1M-triangle render's 140 ms of tracer set-up
// on one core (issue 31, docs/benchmarks.md), while what they come to is a few thousand boxes.
//
// The key is the grid's cache key (accel/grid_cache.h: every position the blocks are found
// from, the grid options, the builder's sources), the start-box cap, the entry format and the
// extent's own sources. An entry that passes the cache's checksum but does not hold a
// well-formed extent is removed with one warning line and the extent found anew.
#include <cstddef>
#include <string>
#include <string_view>

#include "render/traced_tiles.h"

namespace prism {

class DiskCache;

constexpr uint32_t kExtentCacheFormat = 1;

// How an extent came to be, for --stats.
struct ExtentCacheOutcome {
    std::string state = "off"; // "off" (no cache or no grid key), "hit", or "miss" (found, stored)
    double ms = 0.0;           // the whole: read back, or found and stored
};

std::string extentCacheKey(const std::string &gridKey, size_t maxStartBoxes);
std::string packExtent(const SceneExtent &extent);
SceneExtent unpackExtent(std::string_view bytes); // throws BlobFormatError on a damaged entry

// sceneExtent(scene, grid, maxStartBoxes), through `cache` under the grid's key `gridKey`
// (GridCacheOutcome::key of that same scene and grid); found every time without a cache or key.
SceneExtent sceneExtentCached(const Scene &scene, const Grid &grid, size_t maxStartBoxes,
                              const DiskCache *cache, const std::string &gridKey,
                              ExtentCacheOutcome *outcome = nullptr);

} // namespace prism
