#pragma once
// Which 8x8 tiles of the image the full tracer must run on. A camera ray that misses every box
// that holds geometry and every plane sees only the background (or the environment), and on
// lavapipe the tracer costs nearly as much for such a ray as for one that hits: a SIMD group runs
// every branch of the shader, masked, whatever its lanes take (docs/benchmarks.md, "Where the
// cycles go"). So the tiles whose rays provably miss everything are traced by a variant compiled
// with no geometry, and only the rest by the full tracer, each kind of tile in one dispatch over a
// list of tiles. Tiles whose rays see only planes, out of every shadow the grid's geometry casts
// on them, get a third variant, without the grid (render/plane_shadows.h, tileClasses).
#include <cstdint>
#include <limits>
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

// What a camera ray can hit, in the coordinates the tracer uses: boxes that hold the surface of
// every finite primitive between them (the occupied blocks of a coarse grid over the scene grid's
// box, so that the tiles between the parts of an object are not traced) and the planes as (unit
// normal, offset) with n.p = offset on the plane.
struct SceneExtent {
    std::vector<Aabb> boxes;
    std::vector<glm::dvec4> planes;
    // Finer blocks for tileStartDistances: a tile's rays start their walk at the nearest block
    // they may meet, so small blocks start them nearer the geometry. (The plane shadows keep the
    // coarse ones: they are priced per box. Where a tracer makes the starts, the tiles that see
    // a block are read from them.) Each primitive's own bounds, tried
    // instead where there are few, started rays earlier: a large slanted triangle's bounds
    // reach far in front of it (objects 1.14x trace time, bunny 1.07x).
    std::vector<Aabb> startBoxes;
};

// The blocks of a grid of at most kExtentBlocks per axis over `grid`'s box that the surface of
// some finite primitive of `scene` may meet (FinitePrimitives::surfaceMayMeetBox: exact for
// triangles; a sphere's inside is left out), the same at kStartBlocks per axis, and the planes.
// Each frame projects every box on the host while the device waits, so a scene whose surfaces
// fill many blocks gets coarser ones: at most kMaxExtentBoxes and kMaxStartBoxes (halving the
// blocks per axis down to 8). Without the caps, 5,000 spheres had 1.7 million start blocks,
// 58 ms of host time a frame against a trace of 59.
constexpr uint32_t kExtentBlocks = 32;
constexpr uint32_t kStartBlocks = 128;
constexpr size_t kMaxExtentBoxes = 4096;
constexpr size_t kMaxStartBoxes = 16384;
SceneExtent sceneExtent(const Scene &scene, const Grid &grid,
                        size_t maxStartBoxes = kMaxStartBoxes);

// For each tile of the image (imageTiles, row by row): 1 where a camera ray of `frame`, at any
// sample position in the tile, may hit a box or a plane of `extent`; 0 where every one provably
// misses them all. Conservative: a pixel's margin round each tile and a relative margin on every
// sign test and box, so that no ray the tracer could see hit something is left to the
// background. `starts`, where given, are tileStartDistances of `extent.startBoxes` for the same
// frame: the boxes are then seen where those are finite (the start blocks hold the same
// surfaces, finer), and not projected again.
std::vector<uint8_t> tilesThatMayHit(const gpu::GpuFrameParams &frame, const SceneExtent &extent,
                                     const std::vector<float> *starts = nullptr);

// Which tracer a tile gets. Full: some camera ray may hit a box, or a plane where a shadow ray
// may reach a box. Planes only: the rays may hit planes, and no shadow ray from those hits can
// reach the grid (render/plane_shadows.h), so the tile needs no grid at all, provided nothing
// there starts a secondary ray (the caller's condition). Background: the rays miss everything.
// A list of tilesThatMayHit flags reads as classes too (1: full).
constexpr uint8_t kTileBackground = 0, kTileFull = 1, kTilePlanesOnly = 2;

// For each tile (imageTiles, row by row): its class, by the boxes and planes of `extent` and the
// boxes round the planes' shadow regions (planeShadowBoxes), with the margins of
// tilesThatMayHit (and its `starts`).
std::vector<uint8_t> tileClasses(const gpu::GpuFrameParams &frame, const SceneExtent &extent,
                                 const std::vector<Aabb> &planeShadows,
                                 const std::vector<float> *starts = nullptr);

// For each tile (imageTiles, row by row): a distance along its camera rays before which none
// of them meets a box of `boxes` (kNoBoxAhead where no ray of the tile meets one). The tracer
// starts a camera ray's grid walk there: the walk from the grid's entry crossed every empty
// cell between the camera and the geometry, up to two thirds of a ray's cells (tori of 1M
// triangles: 4.8 of 7.3 cells a ray that hits; docs/benchmarks.md, "Camera rays start at
// the geometry"). The boxes must hold every finite primitive's surface (sceneExtent's do).
constexpr float kNoBoxAhead = std::numeric_limits<float>::max();
std::vector<float> tileStartDistances(const gpu::GpuFrameParams &frame,
                                      const std::vector<Aabb> &boxes);

// The tiles to dispatch, as x | y << 16 (in tiles), by class (tileClasses): the first `full` for
// the full tracer, then up to `traced` for the tracer of planes only, the rest for the variant
// that only sees the background. Within each part, rows in spreadRowOrder.
//
// Why the order matters: lavapipe hands each of its threads one contiguous share of a
// dispatch's workgroups (llvmpipe's lp_cs_tpool: iter_per_thread = workgroups / threads), and a
// dispatch ends when the busiest thread does. Row by row, one thread got the top of the image
// and the other the bottom; where the costly rows lie in one half (a sky above a floor), one
// thread idled for much of the frame. Rows in bit-reversed order give every contiguous share
// rows from all over the image, so the shares cost about the same for any number of threads,
// and each row's tiles still go to one thread together. Where the number of threads is known
// (`shares`), share s takes the rows r = s (mod shares) in order instead: as balanced, and the
// threads sweep the image down side by side, neighbouring rows at once, so that what one row
// reads is still in the shared cache for the next (one run of 15 frames each against the
// bit-reversed order, median wall time: tori of 100k triangles 0.95x, 1M 0.98x, the full
// bunny 0.96x, others 0.99-1.01x).
struct TileLists {
    std::vector<uint32_t> tiles;
    std::vector<float> starts; // each tile's tileStartDistances entry (0: from the eye)
    uint32_t full = 0;
    uint32_t traced = 0;
};
// `classes` and `starts` are per tile of `image`; only the tiles inside `window` are listed
// (a region's render, render/image_region.h; empty: every tile).
TileLists tileLists(const std::vector<uint8_t> &classes, const TileRect &image,
                    const std::vector<float> &starts = {}, uint32_t shares = 0,
                    const TileRect &window = {});
// Every tile of `image` (inside `window`, where given) for the full tracer (culling off).
TileLists allTiles(const TileRect &image, const TileRect &window = {});
// The tiles that hold some pixel of [x0, x1) x [y0, y1).
inline TileRect tilesCovering(uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
    return {x0 / kTileSize, y0 / kTileSize, (x1 + kTileSize - 1) / kTileSize,
            (y1 + kTileSize - 1) / kTileSize};
}
// 0 .. rows - 1 for a dispatch that `shares` threads split into contiguous shares: with
// shares > 0, the rows r = s (mod shares) in order for s = 0, 1, ... (0, 2, 4, 6, 1, 3, 5, 7 for
// 8 rows and 2); with 0 (unknown), the order of their bit-reversed indices (0, 4, 2, 6, 1, 5,
// 3, 7 for 8).
std::vector<uint32_t> spreadRowOrder(uint32_t rows, uint32_t shares = 0);
inline uint32_t packTile(uint32_t x, uint32_t y) {
    return x | (y << 16);
}

} // namespace prism
