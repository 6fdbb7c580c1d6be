#pragma once
// Which 8x8 tiles of the image the full tracer must run on. A camera ray that misses the grid's
// box and every plane sees only the background (or the environment), and on lavapipe the tracer
// costs nearly as much for such a ray as for one that hits: a SIMD group runs every branch of the
// shader, masked, whatever its lanes take (docs/benchmarks.md, "Where the cycles go"). So the
// tiles whose rays provably miss everything are traced by a variant compiled with no geometry,
// and only the rectangle around the rest by the full tracer.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

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

// What a camera ray can hit, in the coordinates the tracer uses: the grid's box (it holds every
// finite primitive) and the planes as (unit normal, offset) with n.p = offset on the plane.
struct SceneExtent {
    bool hasBox = false;
    glm::dvec3 boxMin{0.0}, boxMax{0.0};
    std::vector<glm::dvec4> planes;
};

// `hasFinite`: the scene has spheres, triangles or instances (else the grid's box holds nothing).
SceneExtent sceneExtent(const Scene &scene, const Grid &grid, bool hasFinite);

// The smallest rectangle of tiles outside which every camera ray of `frame` (at any sample
// position in its pixel) misses everything in `extent`: conservative, with a pixel's margin
// round each tile and a relative margin on every sign test, so that no ray the tracer could see
// hit something is left to the background.
TileRect tilesThatMayHit(const gpu::GpuFrameParams &frame, const SceneExtent &extent);

// The rest of `image`'s tiles (imageTiles) as at most four rectangles (above, below, left,
// right of `traced`), for the variant that only sees the background.
std::vector<TileRect> tilesAround(const TileRect &traced, const TileRect &image);

} // namespace prism
