// Building the grid: bounds, resolution, then each primitive into the cells it overlaps,
// gathered as (cell, primitive) pairs and counting-sorted into CSR arrays.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "accel/adaptive_grid.h"
#include "accel/bounds.h"
#include "accel/cell_binner.h"
#include "accel/finite_primitives.h"
#include "accel/grid.h"
#include "accel/grid_choice.h"
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

void fillCells(Grid &grid, const std::vector<std::pair<uint32_t, uint32_t>> &pairs) {
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

Lattice wholeGrid(const Grid &grid) {
    Lattice l;
    l.origin = glm::dvec3(grid.boundsMin);
    l.cellSize = glm::dvec3(grid.cellSize);
    l.lo = glm::ivec3(0);
    l.hi = grid.resolution;
    glm::dvec3 mag =
        glm::max(glm::abs(glm::dvec3(grid.boundsMin)), glm::abs(glm::dvec3(grid.boundsMax)));
    l.magnitude = std::max({mag.x, mag.y, mag.z});
    return l;
}

namespace {

// The grid's box, resolution and cell size for `options`, no cells yet: what a walk through it
// needs (grid_choice.h prices a regular grid by the cells its walks would cross).
Grid layOutGrid(const FinitePrimitives &finite, const GridOptions &options) {
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
    grid.lean = buildsLean(options, primitives);
    switch (options.mode) {
    case GridOptions::Mode::Off:
        grid.resolution = glm::ivec3(1);
        break;
    case GridOptions::Mode::Fixed:
        grid.resolution = options.resolution;
        break;
    case GridOptions::Mode::Adaptive:
    case GridOptions::Mode::TwoLevel:
        grid.resolution = chooseResolution(glm::dvec3(grid.boundsMax - grid.boundsMin), primitives,
                                           kAdaptiveTopDensity);
        break;
    case GridOptions::Mode::Auto:
    case GridOptions::Mode::Regular:
        grid.resolution = chooseResolution(glm::dvec3(grid.boundsMax - grid.boundsMin), primitives,
                                           double(options.density));
        break;
    }
    if (grid.topCellCount() > kMaxGridCells)
        throw Error("grid of " + std::to_string(grid.topCellCount()) + " cells is more than " +
                    std::to_string(kMaxGridCells));
    grid.cellSize = (grid.boundsMax - grid.boundsMin) / glm::vec3(grid.resolution);
    return grid;
}

Grid buildOneGrid(const Scene &scene, const GridOptions &options) {
    FinitePrimitives finite(scene);
    Grid grid = layOutGrid(finite, options);
    uint32_t primitives = finite.count();
    if (options.mode == GridOptions::Mode::Off) {
        grid.cellStart = {0u, uint32_t(primitives)};
        grid.cellPrimitives.resize(primitives);
        for (uint32_t id = 0; id < primitives; ++id)
            grid.cellPrimitives[id] = id;
        grid.maxPerCell = uint32_t(primitives);
        return grid;
    }

    if (options.mode == GridOptions::Mode::Adaptive) {
        buildAdaptiveCells(grid, finite, options);
        return grid;
    }
    if (options.mode == GridOptions::Mode::TwoLevel) {
        buildAdaptiveCells(grid, finite, options, kTwoLevelStyle);
        return grid;
    }
    CellBinner binner(wholeGrid(grid));
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t id = 0; id < primitives; ++id)
        binner.bin(id, finite, pairs);
    fillCells(grid, pairs);
    return grid;
}

// A prototype's grid: regular, at the default density, whatever the scene's grid is (a single
// mesh is spread evenly enough for one; --grid chooses the level the instances are in).
std::vector<Grid> buildMeshGrids(const Scene &scene) {
    std::vector<Grid> grids;
    for (const MeshPrototype &prototype : scene.prototypes) {
        Scene mesh;
        mesh.triangles = prototype.triangles;
        grids.push_back(buildOneGrid(mesh, GridOptions{GridOptions::Mode::Regular}));
    }
    return grids;
}

} // namespace

Grid buildGrid(const Scene &scene, const GridOptions &options) {
    return buildGridOverMeshGrids(scene, options, buildMeshGrids(scene));
}

Grid buildGridOverMeshGrids(const Scene &scene, const GridOptions &options,
                            const std::vector<Grid> &meshGrids) {
    if (meshGrids.size() != scene.prototypes.size())
        throw Error("mesh grids for " + std::to_string(meshGrids.size()) + " prototypes, not " +
                    std::to_string(scene.prototypes.size()));
    auto build = [&](GridOptions::Mode mode) {
        GridOptions one = options;
        one.mode = mode;
        Grid grid = buildOneGrid(scene, one);
        grid.meshGrids = meshGrids;
        return grid;
    };
    if (options.mode != GridOptions::Mode::Auto)
        return build(options.mode);
    auto regularLayout = [&] {
        GridOptions regular = options;
        regular.mode = GridOptions::Mode::Regular;
        return layOutGrid(FinitePrimitives(scene), regular);
    };
    return chooseGrid(scene, build, regularLayout);
}

Grid rebuildInstanceLevel(const Scene &scene, Grid previous, const GridOptions &options) {
    // --grid auto keeps the kind it chose at the first frame: the tracer's variant follows the
    // kind, and a choice made again each frame could switch it (and recompile) mid-range.
    GridOptions one = options;
    if (one.mode == GridOptions::Mode::Auto)
        one.mode = previous.adaptive() ? GridOptions::Mode::Adaptive : GridOptions::Mode::Regular;
    Grid grid = buildOneGrid(scene, one);
    grid.meshGrids = std::move(previous.meshGrids);
    grid.choice = std::move(previous.choice);
    return grid;
}

} // namespace prism
