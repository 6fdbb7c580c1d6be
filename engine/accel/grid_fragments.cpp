#include "accel/grid_fragments.h"

#include <algorithm>

#include "core/error.h"
#include "core/parallel_for.h"

namespace prism {
namespace {

// Where a fragment's entries (all but its first), cells and references start in the grid.
struct FragmentBase {
    uint64_t entry = 0, cell = 0, reference = 0;
};

// Copies fragment f of top cell `topCell` into the grid's arrays, already sized, from `base`.
void copyFragment(Grid &grid, uint32_t topCell, const Fragment &f, const FragmentBase &base) {
    auto renumber = [&](uint32_t entry) {
        uint32_t split = entry & 15u, target = entry >> 4;
        // Entry 0 is the top cell's own; the fragment's entry j > 0 lands at base.entry + j - 1.
        target = split != 0 ? uint32_t(base.entry) + target - 1 : uint32_t(base.cell) + target;
        return target << 4 | split;
    };
    grid.entries[topCell] = renumber(f.entries[0]);
    for (size_t j = 1; j < f.entries.size(); ++j)
        grid.entries[base.entry + j - 1] = renumber(f.entries[j]);
    std::copy(f.cellBoxes.begin(), f.cellBoxes.end(), grid.cellBoxes.begin() + base.cell);
    uint64_t start = base.reference;
    for (size_t c = 0; c < f.cellCounts.size(); ++c) {
        grid.cellStart[base.cell + c] = uint32_t(start);
        start += f.cellCounts[c];
    }
    std::copy(f.cellPrimitives.begin(), f.cellPrimitives.end(),
              grid.cellPrimitives.begin() + base.reference);
}

} // namespace

void joinFragments(Grid &grid, std::vector<Fragment> &fragments) {
    // Each fragment's place follows from the sizes of those before it (a prefix sum); then
    // every fragment is copied to its own place, in parallel, into arrays sized once.
    std::vector<FragmentBase> bases(fragments.size());
    FragmentBase end{fragments.size(), 0, 0};
    grid.depth = 0;
    grid.maxPerCell = 0;
    for (size_t t = 0; t < fragments.size(); ++t) {
        bases[t] = end;
        end.entry += fragments[t].entries.size() - 1;
        end.cell += fragments[t].cellBoxes.size();
        end.reference += fragments[t].cellPrimitives.size();
        grid.depth = std::max(grid.depth, fragments[t].depth);
        grid.maxPerCell = std::max(grid.maxPerCell, fragments[t].maxPerCell);
    }
    if (end.entry + 1 > kMaxAdaptiveIndex)
        throw Error("adaptive grid needs more than 2^28 voxel-map entries; use --grid regular");
    if (end.cell > kMaxAdaptiveIndex)
        throw Error("adaptive grid needs more than 2^28 cells; use --grid regular");
    if (end.reference >= uint64_t(UINT32_MAX))
        throw Error("grid holds more than 2^32 primitive references; use --grid regular");
    grid.entries.assign(end.entry, 0u);
    grid.cellBoxes.resize(end.cell);
    grid.cellStart.resize(end.cell + 1);
    grid.cellStart[end.cell] = uint32_t(end.reference);
    grid.cellPrimitives.resize(end.reference);
    // In blocks of fragments: a small grid is copied without starting a thread.
    constexpr size_t kBlock = 256;
    parallelFor((fragments.size() + kBlock - 1) / kBlock, [&](size_t block) {
        for (size_t t = block * kBlock; t < std::min(fragments.size(), (block + 1) * kBlock); ++t) {
            if (fragments[t].sameCellAs >= 0)
                grid.entries[t] = uint32_t(bases[size_t(fragments[t].sameCellAs)].cell) << 4;
            else
                copyFragment(grid, uint32_t(t), fragments[t], bases[t]);
            fragments[t] = {};
        }
    });
}

} // namespace prism
