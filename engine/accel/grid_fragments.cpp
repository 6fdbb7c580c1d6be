#include "accel/grid_fragments.h"

#include <algorithm>
#include <array>
#include <functional>

#include "core/error.h"
#include "core/parallel_for.h"

namespace prism {
namespace {

// Where a fragment's entries (all but its first), cells and references start in the grid.
struct FragmentBase {
    uint64_t entry = 0, cell = 0, reference = 0;
};

// Cells and references from which the arrays are appended on several threads.
constexpr uint64_t kParallelJoinFrom = 65'536;

// A fragment's entry j renumbered into the grid: entry 0 is the top cell's own, and entry j > 0
// lands at base.entry + j - 1; a leaf's cell index at base.cell on.
uint32_t renumber(uint32_t entry, const FragmentBase &base) {
    uint32_t split = entry & 15u, target = entry >> 4;
    target = split != 0 ? uint32_t(base.entry) + target - 1 : uint32_t(base.cell) + target;
    return target << 4 | split;
}

// Gives a fragment's memory back (assigning an empty Fragment would allocate its first entry).
void release(Fragment &f) {
    std::vector<uint32_t>().swap(f.entries);
    std::vector<glm::uvec4>().swap(f.cellBoxes);
    std::vector<uint32_t>().swap(f.cellCounts);
    std::vector<uint32_t>().swap(f.cellPrimitives);
}

} // namespace

void joinFragments(Grid &grid, std::vector<Fragment> &fragments) {
    // Each fragment's place follows from the sizes of those before it (a prefix sum), which
    // renumbers its entries; then each array is appended (below).
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
    // Each array is appended whole by one thread, fragment after fragment, into storage
    // reserved once: written once, where sizing the arrays first filled them with zeros on one
    // thread before the copies (2.3 of a 100k-triangle lean build's 4.2 ms of joining).
    auto entries = [&] {
        grid.entries.clear();
        grid.entries.reserve(end.entry);
        for (size_t t = 0; t < fragments.size(); ++t) {
            const Fragment &f = fragments[t];
            grid.entries.push_back(f.sameCellAs >= 0
                                       ? uint32_t(bases[size_t(f.sameCellAs)].cell) << 4
                                       : renumber(f.entries[0], bases[t]));
        }
        for (size_t t = 0; t < fragments.size(); ++t)
            if (fragments[t].sameCellAs < 0)
                for (size_t j = 1; j < fragments[t].entries.size(); ++j)
                    grid.entries.push_back(renumber(fragments[t].entries[j], bases[t]));
    };
    auto cellBoxes = [&] {
        grid.cellBoxes.clear();
        grid.cellBoxes.reserve(end.cell);
        for (const Fragment &f : fragments)
            grid.cellBoxes.insert(grid.cellBoxes.end(), f.cellBoxes.begin(), f.cellBoxes.end());
    };
    auto cellStart = [&] {
        grid.cellStart.clear();
        grid.cellStart.reserve(end.cell + 1);
        uint32_t start = 0;
        for (const Fragment &f : fragments)
            for (uint32_t count : f.cellCounts) {
                grid.cellStart.push_back(start);
                start += count;
            }
        grid.cellStart.push_back(start);
    };
    auto cellPrimitives = [&] {
        grid.cellPrimitives.clear();
        grid.cellPrimitives.reserve(end.reference);
        for (const Fragment &f : fragments)
            grid.cellPrimitives.insert(grid.cellPrimitives.end(), f.cellPrimitives.begin(),
                                       f.cellPrimitives.end());
    };
    // The two largest first, so that two threads take one of them each; a small grid's on
    // this thread, without waking another.
    const std::array<std::function<void()>, 4> appends{cellBoxes, cellPrimitives, entries,
                                                       cellStart};
    auto append = [&](size_t array) { appends[array](); };
    if (end.cell + end.reference < kParallelJoinFrom) {
        for (size_t array = 0; array < 4; ++array)
            append(array);
    } else {
        parallelFor(4, append);
    }
    // In blocks of fragments: a small grid's are given back without starting a thread.
    constexpr size_t kBlock = 256;
    parallelFor((fragments.size() + kBlock - 1) / kBlock, [&](size_t block) {
        for (size_t t = block * kBlock; t < std::min(fragments.size(), (block + 1) * kBlock); ++t)
            release(fragments[t]);
    });
}

} // namespace prism
