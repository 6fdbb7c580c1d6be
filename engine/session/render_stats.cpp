#include "session/render_stats.h"

#include <algorithm>
#include <cstdint>

namespace prism {
namespace {

std::string resolutionText(const glm::ivec3 &r) {
    return std::to_string(r.x) + "x" + std::to_string(r.y) + "x" + std::to_string(r.z);
}

} // namespace

std::string gridText(const Grid &grid) {
    const char *lean = grid.lean ? ", lean" : "";
    if (!grid.adaptive())
        return resolutionText(grid.resolution) + lean;
    return "adaptive " + resolutionText(grid.resolution) + " top, " +
           std::to_string(grid.cellCount()) + " cells, depth " + std::to_string(grid.depth) + lean;
}

nlohmann::json sceneStats(const PreparedScene &prepared) {
    const Scene &scene = prepared.scene;
    const Grid &grid = prepared.grid;
    // Instances: the triangles stored (the scene's and each prototype's once) against the
    // triangles the placements draw.
    uint64_t placedTriangles = 0;
    for (const Instance &i : scene.instances)
        placedTriangles += scene.prototypes[i.prototype].triangles.size();
    const GridCacheOutcome &cache = prepared.gridCache;
    return {{"primitives", scene.finitePrimitiveCount() + scene.planes.size()},
            {"grid", gridText(grid)},
            {"grid_cells", grid.cellCount()},
            {"grid_bytes", grid.bytes()},
            {"grid_mean_per_cell",
             double(grid.cellPrimitives.size()) / double(std::max<uint64_t>(1, grid.cellCount()))},
            {"grid_max_per_cell", grid.maxPerCell},
            {"grid_choice", grid.choice},
            {"grid_build", grid.lean ? "lean" : "full"},
            {"triangles",
             {{"scene", scene.triangles.size()},
              {"prototypes", scene.prototypeTriangleCount()},
              {"instances", scene.instances.size()},
              {"placed", placedTriangles}}},
            {"build_ms", prepared.buildMs},
            {"grid_cache",
             {{"state", cache.state},
              {"key_ms", cache.keyMs},
              {"read_ms", cache.readMs},
              {"store_ms", cache.storeMs}}},
            {"extent_cache", // the tiles' extent, found with the grid (PreparedScene::extent)
             {{"state", prepared.extentCache.state}, {"ms", prepared.extentCache.ms}}}};
}

nlohmann::json objCacheStats(const ObjCacheUse &use) {
    return {{"hits", use.hits},
            {"misses", use.misses},
            {"key_ms", use.keyMs},
            {"read_ms", use.readMs},
            {"store_ms", use.storeMs}};
}

nlohmann::json frameStats(const RayCounts &rays, double traceMs, uint32_t resumeDispatches) {
    return {{"rays",
             {{"primary", rays.primary}, {"shadow", rays.shadow}, {"secondary", rays.secondary}}},
            {"mrays_per_s", double(rays.total()) / (traceMs * 1e3)},
            {"resume_dispatches", resumeDispatches}};
}

nlohmann::json tileStats(const std::array<uint32_t, 3> &tiles) {
    return {{"full", tiles[0]}, {"planes_only", tiles[1]}, {"background", tiles[2]}};
}

nlohmann::json gpuBytesStats(const std::vector<ArrayBytes> &arrays) {
    nlohmann::json bytes;
    uint64_t total = 0;
    for (const ArrayBytes &a : arrays) {
        bytes[a.what] = a.bytes;
        total += a.bytes;
    }
    bytes["total"] = total;
    return bytes;
}

} // namespace prism
