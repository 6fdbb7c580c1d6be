#include "accel/grid_walk.h"

#include <algorithm>
#include <limits>

namespace prism {

namespace {

// From cell to cell: each cell's box is left through its nearest exit face, and the next cell is
// the one holding the voxel just past that face at the exit point (the other coordinates kept
// inside the box, so the walk always moves on).
void walkAdaptive(const Grid &grid, const glm::dvec3 &origin, const glm::dvec3 &dir, double tEnter,
                  double tExit, const std::function<bool(uint32_t, double, double)> &visit) {
    glm::dvec3 lo(grid.boundsMin), voxel(grid.voxelSize());
    glm::ivec3 res = grid.voxelResolution();
    glm::ivec3 v = glm::clamp(glm::ivec3(glm::floor((origin + tEnter * dir - lo) / voxel)),
                              glm::ivec3(0), res - 1);
    double t = tEnter;
    for (;;) {
        uint32_t cell = adaptiveCellAt(grid, v);
        glm::ivec3 bmin, bmax;
        unpackCellBox(grid.cellBoxes[cell], bmin, bmax);
        double tCellExit = tExit;
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            if (dir[a] == 0.0)
                continue;
            double face = lo[a] + double(dir[a] > 0.0 ? bmax[a] : bmin[a]) * voxel[a];
            double tFace = (face - origin[a]) / dir[a];
            if (tFace < tCellExit) {
                tCellExit = tFace;
                axis = a;
            }
        }
        tCellExit = std::max(tCellExit, t);
        if (!visit(cell, t, tCellExit) || axis < 0)
            return;
        glm::dvec3 exitPoint = origin + tCellExit * dir;
        for (int a = 0; a < 3; ++a) {
            // Inside the box, and never against the ray (see stepBoxWalk in traverse.glsl).
            int next = std::clamp(int(std::floor((exitPoint[a] - lo[a]) / voxel[a])), bmin[a],
                                  bmax[a] - 1);
            v[a] = dir[a] > 0.0 ? std::max(next, v[a]) : std::min(next, v[a]);
        }
        v[axis] = dir[axis] > 0.0 ? bmax[axis] : bmin[axis] - 1;
        if (v[axis] < 0 || v[axis] >= res[axis])
            return;
        t = tCellExit;
    }
}

} // namespace

void walkGrid(const Grid &grid, const glm::dvec3 &origin, const glm::dvec3 &dir, double tMax,
              const std::function<bool(uint32_t, double, double)> &visit) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    glm::dvec3 lo(grid.boundsMin), hi(grid.boundsMax), cellSize(grid.cellSize);
    double tEnter = 0.0, tExit = tMax;
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0.0) {
            if (origin[a] < lo[a] || origin[a] > hi[a])
                return;
            continue;
        }
        double t0 = (lo[a] - origin[a]) / dir[a], t1 = (hi[a] - origin[a]) / dir[a];
        tEnter = std::max(tEnter, std::min(t0, t1));
        tExit = std::min(tExit, std::max(t0, t1));
    }
    if (tEnter > tExit)
        return;
    if (grid.adaptive()) {
        walkAdaptive(grid, origin, dir, tEnter, tExit, visit);
        return;
    }
    glm::dvec3 entry = origin + tEnter * dir;
    glm::ivec3 cell = glm::clamp(glm::ivec3(glm::floor((entry - lo) / cellSize)), glm::ivec3(0),
                                 grid.resolution - 1);
    glm::ivec3 step(0);
    glm::dvec3 tNext(kInf), tDelta(kInf);
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0.0)
            continue;
        step[a] = dir[a] > 0.0 ? 1 : -1;
        double face = lo[a] + (cell[a] + (step[a] > 0 ? 1 : 0)) * cellSize[a];
        tNext[a] = (face - origin[a]) / dir[a];
        tDelta[a] = cellSize[a] / std::abs(dir[a]);
    }
    double t = tEnter;
    for (;;) {
        double tCellExit = std::min({tNext.x, tNext.y, tNext.z, tExit});
        if (!visit(grid.cellIndex(cell), t, tCellExit) || tCellExit >= tExit)
            return;
        int axis = tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= grid.resolution[axis])
            return;
        t = tNext[axis];
        tNext[axis] += tDelta[axis];
    }
}

} // namespace prism
