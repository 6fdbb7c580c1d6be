#include "render/loop_bound.h"

#include <algorithm>
#include <functional>
#include <vector>

namespace prism {
namespace {

// Saturating arithmetic: the bound only needs to be compared with a budget.
constexpr uint64_t kSaturated = uint64_t(1) << 62;
uint64_t add(uint64_t a, uint64_t b) {
    return std::min(kSaturated, a + b);
}
uint64_t mul(uint64_t a, uint64_t b) {
    return (a != 0 && b > kSaturated / a) ? kSaturated : std::min(kSaturated, a * b);
}

} // namespace

uint64_t traversalIterationBound(const Scene &scene, const Grid &grid) {
    uint64_t iterations = add(scene.planes.size(), 1); // +1: every loop may count its exit too
    if (scene.finitePrimitiveCount() == 0)
        return iterations;
    // A ray crosses at most one cell per voxel boundary (regular grid: voxels are its cells).
    glm::ivec3 voxels = grid.voxelResolution();
    uint64_t cellsCrossed = uint64_t(voxels.x) + voxels.y + voxels.z;
    std::vector<uint32_t> counts(grid.cellStart.size() - 1);
    for (size_t c = 0; c < counts.size(); ++c)
        counts[c] = grid.cellStart[c + 1] - grid.cellStart[c];
    size_t k = std::min<size_t>(cellsCrossed, counts.size());
    std::partial_sort(counts.begin(), counts.begin() + k, counts.end(), std::greater<>());
    uint64_t tests = 0;
    for (size_t c = 0; c < k; ++c)
        tests += counts[c];
    // DDA steps and their exits, the cells' primitive loops and their exits; in an adaptive
    // grid each step also walks the voxel map down to its cell.
    uint64_t lookups = grid.adaptive() ? mul(cellsCrossed, grid.depth + 1) : 0;
    return add(add(iterations, lookups),
               add(mul(2, add(cellsCrossed, 1)), add(tests, cellsCrossed)));
}

uint64_t invocationIterationBound(const Scene &scene, const Grid &grid,
                                  const TracerFeatures &features) {
    uint64_t traversal = traversalIterationBound(scene, grid);
    uint64_t lights = scene.lights.size();
    // Per light: its iteration, the stratified light sample's short strata loops (<= 8), and
    // the shadow ray's traversal.
    uint64_t perLight = add(9, features.shadows ? traversal : 0);
    uint64_t perRay = add(add(2, traversal), mul(lights, perLight));
    // A hit pushes a reflected ray where it reflects, a reflected and a refracted one where it
    // transmits.
    uint64_t children = (features.reflection ? 1 : 0) + (features.transmission ? 2 : 0);
    uint64_t rays = 0, level = 1;
    for (uint32_t depth = 1; depth <= features.maxDepth; ++depth) {
        rays = add(rays, level);
        level = mul(level, children);
    }
    uint64_t total = mul(rays, perRay);
    if (features.writeAov)
        total = add(total, traversal);
    return add(total, 64); // the sample-position helpers' short loops
}

} // namespace prism
