#pragma once
// The CPU twin of the shader's 3D-DDA (Amanatides & Woo 1987), in double: visits the cells a
// ray crosses, in order, with the ray's parametric range inside each. Tests use it to check
// that the grid lists every primitive where a ray can meet it.
#include <functional>

#include <glm/glm.hpp>

#include "accel/grid.h"

namespace prism {

// Calls visit(cellIndex, tEnter, tExit) for each cell the ray (origin + t * dir, 0 <= t <
// tMax) crosses, nearest first, until visit returns false or the ray leaves the grid.
// The adaptive grid's cell that holds voxel v (voxel coordinates in [0, voxelResolution())).
// Down the voxel map from v's top cell, as the tracer does (traverse.glsl). Inline: the
// expansion's face queries make millions of these lookups.
inline uint32_t adaptiveCellAt(const Grid &grid, glm::ivec3 v) {
    uint32_t entry = grid.entries[grid.cellIndex(v >> int(grid.shift))];
    int shift = int(grid.shift);
    while ((entry & 15u) != 0) {
        int split = int(entry & 15u);
        shift -= split;
        glm::ivec3 part = (v >> shift) & ((1 << split) - 1);
        entry = grid.entries[(entry >> 4) +
                             uint32_t(part.x + (part.y << split) + (part.z << (2 * split)))];
    }
    return entry >> 4;
}

void walkGrid(const Grid &grid, const glm::dvec3 &origin, const glm::dvec3 &dir, double tMax,
              const std::function<bool(uint32_t cell, double tEnter, double tExit)> &visit);

} // namespace prism
