#include "accel/cell_expansion.h"

#include <algorithm>
#include <vector>

#include "core/parallel_for.h"

namespace prism {
namespace {

// Calls visit(cell) for the cells of the voxel map that overlap the voxel box [lo, hi), until
// one returns false. Returns whether all returned true. (A cell covering several entries of
// the map may be visited more than once.)
template <typename Visit> class MapQuery {
public:
    MapQuery(const Grid &grid, glm::ivec3 lo, glm::ivec3 hi, Visit &visit)
        : grid_(grid), lo_(lo), hi_(hi), visit_(visit) {}

    bool run() {
        int shift = int(grid_.shift);
        glm::ivec3 first = lo_ >> shift, last = (hi_ - 1) >> shift;
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    glm::ivec3 top(x, y, z);
                    if (!descend(grid_.entries[grid_.cellIndex(top)], top << shift, shift))
                        return false;
                }
        return true;
    }

private:
    bool descend(uint32_t entry, glm::ivec3 nodeMin, int nodeShift) {
        int split = int(entry & 15u);
        if (split == 0)
            return visit_(entry >> 4);
        int childShift = nodeShift - split, parts = 1 << split;
        glm::ivec3 first = glm::max(lo_ - nodeMin, glm::ivec3(0)) >> childShift;
        glm::ivec3 last = glm::min((hi_ - 1 - nodeMin) >> childShift, glm::ivec3(parts - 1));
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    uint32_t child = (entry >> 4) + uint32_t(x + (y << split) + (z << (2 * split)));
                    if (!descend(grid_.entries[child],
                                 nodeMin + (glm::ivec3(x, y, z) << childShift), childShift))
                        return false;
                }
        return true;
    }

    const Grid &grid_;
    glm::ivec3 lo_, hi_;
    Visit &visit_;
};

template <typename Visit>
bool allCellsIn(const Grid &grid, glm::ivec3 lo, glm::ivec3 hi, Visit visit) {
    return MapQuery<Visit>(grid, lo, hi, visit).run();
}

// Cell `cell`'s box after expansion; reads only the grid as built.
glm::uvec4 expandedBox(const Grid &grid, uint32_t cell) {
    glm::ivec3 resolution = grid.voxelResolution();
    auto refs = [&](uint32_t c) {
        return std::make_pair(grid.cellPrimitives.begin() + grid.cellStart[c],
                              grid.cellPrimitives.begin() + grid.cellStart[c + 1]);
    };
    glm::ivec3 lo, hi;
    unpackCellBox(grid.cellBoxes[cell], lo, hi);
    auto [first, last] = refs(cell);
    for (int round = 0; round < kExpansionRounds; ++round) {
        bool grew = false;
        for (int face = 0; face < 6; ++face) {
            int axis = face / 2;
            bool up = face % 2 == 0;
            if (up ? hi[axis] >= resolution[axis] : lo[axis] <= 0)
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
            uint32_t previous = ~0u; // a merged cell comes up once for each of its map entries
            bool allowed = allCellsIn(grid, layerLo, layerHi, [&](uint32_t neighbour) {
                if (neighbour == previous)
                    return true;
                previous = neighbour;
                auto [nFirst, nLast] = refs(neighbour);
                if (nLast - nFirst > last - first || !std::includes(first, last, nFirst, nLast))
                    return false;
                glm::ivec3 nLo, nHi;
                unpackCellBox(grid.cellBoxes[neighbour], nLo, nHi);
                step = std::min(step, up ? nHi[axis] - hi[axis] : lo[axis] - nLo[axis]);
                return true;
            });
            if (!allowed || step <= 0)
                continue;
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
    std::vector<glm::uvec4> grown(cells);
    parallelFor((cells + kBlock - 1) / kBlock, [&](size_t block) {
        for (size_t cell = block * kBlock; cell < std::min(cells, (block + 1) * kBlock); ++cell)
            grown[cell] = expandedBox(grid, uint32_t(cell));
    });
    grid.cellBoxes = std::move(grown);
}

} // namespace prism
