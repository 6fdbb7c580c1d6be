// Building the grid: bounds, resolution, then each primitive into the cells it overlaps,
// gathered as (cell, primitive) pairs and counting-sorted into CSR arrays.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "accel/bounds.h"
#include "accel/finite_primitives.h"
#include "accel/grid.h"
#include "accel/grid_resolution.h"
#include "core/error.h"

namespace prism {
namespace {

Aabb finiteBounds(const FinitePrimitives &primitives) {
    Aabb b;
    for (uint32_t id = 0; id < primitives.count(); ++id)
        b.grow(primitives.bounds(id));
    return b;
}

// Bounds padded a little so that primitives on the boundary lie strictly inside, in float.
Aabb paddedBounds(Aabb b) {
    if (b.empty())
        return {glm::dvec3(-0.5), glm::dvec3(0.5)};
    glm::dvec3 e = b.extent();
    double largest = std::max({e.x, e.y, e.z});
    double magnitude = std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z),
                                 std::abs(b.max.x), std::abs(b.max.y), std::abs(b.max.z)});
    double pad = 1e-4 * largest + 1e-6 * magnitude;
    if (pad == 0.0)
        pad = 1e-6;
    return {b.min - pad, b.max + pad};
}

// Pairs list each (cell, primitive id) overlap once; ids as in scene/primitive_ids.h.
class CellBinner {
public:
    explicit CellBinner(const Grid &grid) : grid_(grid) {
        glm::dvec3 cell(grid.cellSize), mag = glm::max(glm::abs(glm::dvec3(grid.boundsMin)),
                                                       glm::abs(glm::dvec3(grid.boundsMax)));
        double largest = std::max({mag.x, mag.y, mag.z});
        // Cells are widened a little so a hit found by the shader's float DDA near a cell face
        // is listed in the cell on either side of it (rounding may put the walk in either).
        slack_ = 1e-4 * cell + glm::dvec3(4e-7 * largest);
    }

    void bin(uint32_t id, const FinitePrimitives &primitives) {
        Aabb bounds = primitives.bounds(id);
        glm::ivec3 lo = cellOf(bounds.min - slack_), hi = cellOf(bounds.max + slack_);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    glm::dvec3 cmin = glm::dvec3(grid_.boundsMin) +
                                      glm::dvec3(x, y, z) * glm::dvec3(grid_.cellSize);
                    glm::dvec3 cmax = cmin + glm::dvec3(grid_.cellSize);
                    if (primitives.overlapsBox(id, cmin - slack_, cmax + slack_))
                        pairs_.emplace_back(grid_.cellIndex({x, y, z}), id);
                }
    }

    std::vector<std::pair<uint32_t, uint32_t>> &pairs() { return pairs_; }

private:
    glm::ivec3 cellOf(const glm::dvec3 &p) const {
        glm::dvec3 f = glm::floor((p - glm::dvec3(grid_.boundsMin)) / glm::dvec3(grid_.cellSize));
        return glm::clamp(glm::ivec3(glm::clamp(f, glm::dvec3(-1.0), glm::dvec3(1e9))),
                          glm::ivec3(0), grid_.resolution - 1);
    }

    const Grid &grid_;
    glm::dvec3 slack_;
    std::vector<std::pair<uint32_t, uint32_t>> pairs_;
};

void fillCells(Grid &grid, std::vector<std::pair<uint32_t, uint32_t>> &pairs) {
    uint64_t cells = grid.cellCount();
    if (pairs.size() >= uint64_t(UINT32_MAX))
        throw Error("grid holds more than 2^32 primitive references; use a coarser --grid");
    grid.cellStart.assign(cells + 1, 0u);
    for (const auto &[cell, id] : pairs)
        ++grid.cellStart[cell + 1];
    for (uint64_t c = 0; c < cells; ++c) {
        uint32_t count = grid.cellStart[c + 1];
        grid.maxPerCell = std::max(grid.maxPerCell, count);
        grid.cellStart[c + 1] += grid.cellStart[c];
    }
    // Stable counting sort: ids stay in increasing order within a cell.
    grid.cellPrimitives.resize(pairs.size());
    std::vector<uint32_t> cursor(grid.cellStart.begin(), grid.cellStart.end() - 1);
    for (const auto &[cell, id] : pairs)
        grid.cellPrimitives[cursor[cell]++] = id;
}

} // namespace

Grid buildGrid(const Scene &scene, const GridOptions &options) {
    FinitePrimitives finite(scene);
    Aabb bounds = paddedBounds(finiteBounds(finite));
    Grid grid;
    grid.boundsMin = glm::vec3(bounds.min);
    grid.boundsMax = glm::vec3(bounds.max);
    // Rounding to float must not shrink the box.
    for (int a = 0; a < 3; ++a) {
        if (double(grid.boundsMin[a]) > bounds.min[a])
            grid.boundsMin[a] = std::nextafter(grid.boundsMin[a], -INFINITY);
        if (double(grid.boundsMax[a]) < bounds.max[a])
            grid.boundsMax[a] = std::nextafter(grid.boundsMax[a], INFINITY);
    }
    uint32_t primitives = finite.count();
    switch (options.mode) {
    case GridOptions::Mode::Off:
        grid.resolution = glm::ivec3(1);
        break;
    case GridOptions::Mode::Fixed:
        grid.resolution = options.resolution;
        break;
    case GridOptions::Mode::Auto:
        grid.resolution = chooseResolution(glm::dvec3(grid.boundsMax - grid.boundsMin), primitives,
                                           double(options.density));
        break;
    }
    if (grid.cellCount() > kMaxGridCells)
        throw Error("grid of " + std::to_string(grid.cellCount()) + " cells is more than " +
                    std::to_string(kMaxGridCells));
    grid.cellSize = (grid.boundsMax - grid.boundsMin) / glm::vec3(grid.resolution);

    if (options.mode == GridOptions::Mode::Off) {
        grid.cellStart = {0u, uint32_t(primitives)};
        grid.cellPrimitives.resize(primitives);
        for (uint32_t id = 0; id < primitives; ++id)
            grid.cellPrimitives[id] = id;
        grid.maxPerCell = uint32_t(primitives);
        return grid;
    }

    CellBinner binner(grid);
    for (uint32_t id = 0; id < primitives; ++id)
        binner.bin(id, finite);
    fillCells(grid, binner.pairs());
    return grid;
}

} // namespace prism
