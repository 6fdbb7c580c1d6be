#pragma once
// Built grids kept on disk (cache/disk_cache.h), so that rendering a scene again, in this
// process or the next, reads its grid back instead of building it: a million triangles' grid
// took 1.3-2.8 s to build and 0.1 s to read (issue 31, docs/benchmarks.md).
//
// The key is a digest of everything the build reads: the positions of the finite primitives
// (as centred for rendering), the instances' placements and prototypes, the grid options, the
// camera where `--grid auto` counts its rays, the entry format, and the builder's own sources
// (so a changed builder never meets an old grid). Materials, lights and textures are not in
// it: changing them reuses the grid.
#include <string>

#include "accel/grid.h"

namespace prism {

class DiskCache;

// A digest of what the prototypes' mesh grids are built from (their triangles' positions, and
// the builder's code): equal keys, the same mesh grids (Grid::meshGrids). "" without prototypes.
std::string meshGridsKey(const Scene &scene);

constexpr uint32_t kGridCacheFormat = 2;

// How a grid came to be, for --stats.
struct GridCacheOutcome {
    std::string state = "off"; // "off", "hit", or "miss" (built, then stored)
    std::string key;
    double keyMs = 0.0;   // digesting the scene
    double readMs = 0.0;  // reading and unpacking the entry (hit)
    double storeMs = 0.0; // packing and writing it (miss)
};

struct GridCachePolicy {
    const DiskCache *cache = nullptr; // none: always build
    // gridCacheKey(scene, options), where the caller has it already (prism-view compares keys
    // to keep its grid): the scene is not digested again. Empty: digested here.
    std::string key;
};

std::string gridCacheKey(const Scene &scene, const GridOptions &options);
// The same, with the scene's meshGridsKey given: a caller that needs both (prism-view's reload)
// reads the prototypes' triangles once.
std::string gridCacheKey(const Scene &scene, const GridOptions &options,
                         const std::string &meshKey);
std::string packGrid(const Grid &grid);
Grid unpackGrid(std::string_view bytes); // throws BlobFormatError on a damaged entry

// buildGrid(scene, options), through the cache when the policy has one.
Grid buildGridCached(const Scene &scene, const GridOptions &options, const GridCachePolicy &policy,
                     GridCacheOutcome *outcome = nullptr);

} // namespace prism
