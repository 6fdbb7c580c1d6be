#include "accel/cell_expansion.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "accel/grid_walk.h"
#include "core/error.h"
#include "core/parallel_for.h"

namespace prism {
namespace {

// A cell's box as built (the boxes tile the voxel grid then) and where its primitives start, in
// 16 bytes: the expansion's time goes mostly to fetching these for neighbours, so they are
// small, unpacked once, and a cell's count comes from the next record, usually in the same
// cache line. One more record at the end holds the references' end.
struct CellRecord {
    std::array<uint16_t, 3> lo, hi;
    uint32_t first; // cellPrimitives[first .. (this + 1)->first)

    int min(int axis) const { return lo[size_t(axis)]; }
    int max(int axis) const { return hi[size_t(axis)]; }
    uint32_t count() const { return (this + 1)->first - first; }
};
static_assert(sizeof(CellRecord) == 16);

// In blocks of `block` cells, in parallel.
std::vector<CellRecord> cellRecords(const Grid &grid, size_t block) {
    size_t cells = grid.cellBoxes.size();
    std::vector<CellRecord> records(cells + 1);
    parallelFor((cells + block - 1) / block, [&](size_t b) {
        for (size_t c = b * block; c < std::min(cells, (b + 1) * block); ++c) {
            glm::ivec3 lo, hi;
            unpackCellBox(grid.cellBoxes[c], lo, hi);
            for (int a = 0; a < 3; ++a) {
                records[c].lo[size_t(a)] = uint16_t(lo[a]);
                records[c].hi[size_t(a)] = uint16_t(hi[a]);
            }
            records[c].first = grid.cellStart[c];
        }
    });
    records.back().first = grid.cellStart.back();
    return records;
}

// A rectangle [u0, u1) x [w0, w1) of a layer, in the layer's two in-plane axes.
struct Rect {
    int u0, u1, w0, w1;
};

// Calls visit(cell record) for the cells that the one-voxel layer [lo, hi) across `axis`
// meets, until one returns false; returns whether all returned true. The boxes as built tile the
// grid, so the cell holding a rectangle's first corner covers a rectangle of it at once, and
// the two rectangles left are queried in turn: one lookup per cell (a cell cut by the split
// may come twice), where descending the voxel map met every map entry of a merged cell.
template <typename Visit>
bool eachCellInLayer(const Grid &grid, const std::vector<CellRecord> &cells, glm::ivec3 lo,
                     glm::ivec3 hi, int axis, std::vector<Rect> &stack, Visit visit) {
    int u = (axis + 1) % 3, w = (axis + 2) % 3;
    stack.assign(1, Rect{lo[u], hi[u], lo[w], hi[w]});
    glm::ivec3 corner = lo;
    while (!stack.empty()) {
        Rect r = stack.back();
        stack.pop_back();
        corner[u] = r.u0;
        corner[w] = r.w0;
        const CellRecord &n = cells[adaptiveCellAt(grid, corner)];
        // The cell the map gives holds the corner, so the rectangle shrinks: a map that
        // disagreed with the boxes (a bug) would keep it as it is, for ever.
        if (n.max(u) <= r.u0 || n.max(w) <= r.w0)
            throw Error("adaptive grid: the voxel map and the cell boxes disagree at voxel (" +
                        std::to_string(corner.x) + ", " + std::to_string(corner.y) + ", " +
                        std::to_string(corner.z) + ")");
        if (!visit(n))
            return false;
        int coveredU = std::min(r.u1, n.max(u)), coveredW = std::min(r.w1, n.max(w));
        if (coveredU < r.u1)
            stack.push_back({coveredU, r.u1, r.w0, coveredW});
        if (coveredW < r.w1)
            stack.push_back({r.u0, r.u1, coveredW, r.w1});
    }
    return true;
}

// Cell `cell`'s box after expansion; reads only the grid as built.
glm::uvec4 expandedBox(const Grid &grid, const std::vector<CellRecord> &cells, uint32_t cell,
                       std::vector<Rect> &stack) {
    glm::ivec3 resolution = grid.voxelResolution();
    const CellRecord &self = cells[cell];
    glm::ivec3 lo, hi;
    unpackCellBox(grid.cellBoxes[cell], lo, hi);
    uint32_t count = self.count();
    auto first = grid.cellPrimitives.begin() + self.first, last = first + count;
    // A face that failed stays failed: its layer does not move, and only widens as the other
    // faces grow, so the neighbour that failed it is still there. Skipping it changes nothing.
    std::array<bool, 6> failed{};
    for (int round = 0; round < kExpansionRounds; ++round) {
        bool grew = false;
        for (int face = 0; face < 6; ++face) {
            int axis = face / 2;
            bool up = face % 2 == 0;
            if (failed[face] || (up ? hi[axis] >= resolution[axis] : lo[axis] <= 0))
                continue;
            // The one-voxel layer just past the face: the cells it touches must each be
            // listed in full here; the layer grows to the thinnest of them.
            glm::ivec3 layerLo = lo, layerHi = hi;
            if (up) {
                layerLo[axis] = hi[axis];
                layerHi[axis] = hi[axis] + 1;
            } else {
                layerLo[axis] = lo[axis] - 1;
                layerHi[axis] = lo[axis];
            }
            int step = resolution[axis];
            bool allowed = eachCellInLayer(
                grid, cells, layerLo, layerHi, axis, stack, [&](const CellRecord &n) {
                    uint32_t nCount = n.count();
                    if (nCount > count)
                        return false;
                    auto nFirst = grid.cellPrimitives.begin() + n.first;
                    if (nCount > 0 && !std::includes(first, last, nFirst, nFirst + nCount))
                        return false;
                    step = std::min(step, up ? n.max(axis) - hi[axis] : lo[axis] - n.min(axis));
                    return true;
                });
            if (!allowed) {
                failed[face] = true;
                continue;
            }
            // A cell in the layer reaches past the face, so step >= 1.
            if (up)
                hi[axis] += step;
            else
                lo[axis] -= step;
            grew = true;
        }
        if (!grew)
            break;
    }
    return packCellBox(lo, hi);
}

} // namespace

void expandCells(Grid &grid) {
    // Each cell reads the grid as built and writes only its own box: cells expand in parallel,
    // in blocks of kBlock, with the same result on every run.
    constexpr size_t kBlock = 256;
    size_t cells = grid.cellBoxes.size();
    std::vector<CellRecord> records = cellRecords(grid, 64 * kBlock);
    std::vector<glm::uvec4> grown(cells);
    parallelFor((cells + kBlock - 1) / kBlock, [&](size_t block) {
        std::vector<Rect> stack;
        for (size_t cell = block * kBlock; cell < std::min(cells, (block + 1) * kBlock); ++cell)
            grown[cell] = expandedBox(grid, records, uint32_t(cell), stack);
    });
    grid.cellBoxes = std::move(grown);
}

} // namespace prism
