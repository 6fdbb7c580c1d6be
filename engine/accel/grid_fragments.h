#pragma once
// The adaptive grid is built one top cell at a time, each top cell's subtree apart (a
// fragment), so that top cells can be built in parallel; the fragments are then joined into
// the grid's arrays.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "accel/grid.h"

namespace prism {

// One top cell's subtree. Entries and cells are numbered from 0 within the fragment (entry 0 is
// the top cell's own) and renumbered when the fragments are joined, in top-cell order: the grid
// is the same whatever thread built what.
struct Fragment {
    std::vector<uint32_t> entries{0u};
    std::vector<glm::uvec4> cellBoxes;
    std::vector<uint32_t> cellCounts; // primitives per cell
    std::vector<uint32_t> cellPrimitives;
    uint32_t depth = 0;
    uint32_t maxPerCell = 0;
    // An empty top cell merged with others (accel/empty_merge.h): the top cell whose fragment's
    // first cell is this top cell's too; this fragment then holds nothing else. -1: none.
    int64_t sameCellAs = -1;
};

// Fills grid.entries, cellBoxes, cellStart, cellPrimitives, depth and maxPerCell from one
// fragment per top cell (fragments[t] for top cell t), and empties the fragments. Throws
// prism::Error when the grid would need more than 2^28 entries or cells, or 2^32 references.
void joinFragments(Grid &grid, std::vector<Fragment> &fragments);

} // namespace prism
