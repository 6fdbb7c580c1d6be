#include "accel/grid_walk.h"

#include <algorithm>
#include <limits>

namespace prism {

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
