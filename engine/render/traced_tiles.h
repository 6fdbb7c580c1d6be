#pragma once
// Which 8x8 tiles of the image the full tracer must run on. A camera ray that misses every box
// that holds geometry and every plane sees only the background (or the environment), and on
// lavapipe the tracer costs nearly as much for such a ray as for one that hits: a SIMD group runs
// every branch of the shader, masked, whatever its lanes take (docs/benchmarks.md, "Where the
// cycles go"). So the tiles whose rays provably miss everything are traced by a variant compiled
// with no geometry, and only the rest by the full tracer, each kind of tile in one dispatch over a
// list of tiles.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "accel/bounds.h"
#include "accel/grid.h"
#include "scene/scene.h"
#include "shared/gpu_types.h"

namespace prism {

constexpr uint32_t kTileSize = 8; // the tracer's workgroup is 8x8 pixels

// Tiles [x0, x1) x [y0, y1).
struct TileRect {
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    uint32_t width() const { return empty() ? 0 : x1 - x0; }
    uint32_t height() const { return empty() ? 0 : y1 - y0; }
};

// Every tile of a width x height image.
inline TileRect imageTiles(uint32_t width, uint32_t height) {
    return {0, 0, (width + kTileSize - 1) / kTileSize, (height + kTileSize - 1) / kTileSize};
}

// What a camera ray can hit, in the coordinates the tracer uses: boxes that hold every finite
// primitive between them (the occupied blocks of a coarse grid over the scene grid's box, so
// that the tiles between the parts of an object are not traced) and the planes as (unit normal,
// offset) with n.p = offset on the plane.
struct SceneExtent {
    std::vector<Aabb> boxes;
    std::vector<glm::dvec4> planes;
};

// The blocks of a grid of at most kExtentBlocks per axis over `grid`'s box that some finite
// primitive of `scene` overlaps (FinitePrimitives::overlapsBox: exact for triangles), and the
// planes.
constexpr uint32_t kExtentBlocks = 32;
SceneExtent sceneExtent(const Scene &scene, const Grid &grid);

// For each tile of the image (imageTiles, row by row): 1 where a camera ray of `frame`, at any
// sample position in the tile, may hit a box or a plane of `extent`; 0 where every one provably
// misses them all. Conservative: a pixel's margin round each tile and a relative margin on every
// sign test and box, so that no ray the tracer could see hit something is left to the
// background.
std::vector<uint8_t> tilesThatMayHit(const gpu::GpuFrameParams &frame, const SceneExtent &extent);

// The tiles to dispatch, as x | y << 16 (in tiles): the first `traced` for the full tracer, the
// rest for the variant that only sees the background. Row by row within each part.
struct TileLists {
    std::vector<uint32_t> tiles;
    uint32_t traced = 0;
};
TileLists tileLists(const std::vector<uint8_t> &mayHit, const TileRect &image);
inline uint32_t packTile(uint32_t x, uint32_t y) {
    return x | (y << 16);
}

} // namespace prism
