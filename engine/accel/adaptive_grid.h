#pragma once
// The adaptive grid's cells (accel/grid.h): a coarse top grid whose crowded cells are split,
// level by level, into 2^d parts per axis with d chosen by how many primitives the cell holds,
// until a cell holds few primitives or the levels run out. Every cell lists exactly the
// primitives that overlap its box (with the binner's slack), so a walk that accepts a hit only
// inside the current cell's box finds what brute force finds. A lean grid's cells list more:
// every primitive whose bounding box came down to them, without the exact tests (the walk
// allows a superset; it tests a few more primitives a ray).
#include "accel/finite_primitives.h"
#include "accel/grid.h"

namespace prism {

// Top cells per primitive: coarse on purpose, the levels below refine where it is crowded.
constexpr double kAdaptiveTopDensity = 0.125;
// A cell with at most this many primitives is not split.
constexpr uint32_t kAdaptiveLeafPrimitives = 2;
// Levels below the top grid, and the largest split of one level (2^3 = 8 parts per axis).
constexpr uint32_t kAdaptiveMaxDepth = 4;
constexpr uint32_t kAdaptiveMaxSplit = 3;

// What the build does beyond the top grid. The adaptive grid uses all of it; the two-level grid
// (Kalojanov, Stich & Slusallek 2011, in power-of-two form: --grid two-level) splits each top
// cell once, by density alone, and keeps every part as its own cell, unexpanded, so that the
// benchmarks can set the steps of the irregular grid apart.
struct AdaptiveStyle {
    uint32_t maxDepth = kAdaptiveMaxDepth; // levels below the top grid
    bool costModel = true;                 // price each split (SAH) and keep the cheapest
    bool mergeEmptyParts = true;           // the empty parts of a split become few cells
    bool expand = true;                    // cells grow over neighbours they cover
};
constexpr AdaptiveStyle kTwoLevelStyle{1, false, false, false};

// Fills grid.shift, entries, cellBoxes (expanded unless grid.lean: accel/cell_expansion.h),
// cellStart, cellPrimitives, depth and maxPerCell; the grid's bounds, top resolution and cell size
// are already set. Cells split to about options.density cells per primitive they hold. Throws
// prism::Error when the grid would need more than 2^28 cells or entries.
void buildAdaptiveCells(Grid &grid, const FinitePrimitives &primitives, const GridOptions &options,
                        const AdaptiveStyle &style = {});

} // namespace prism
