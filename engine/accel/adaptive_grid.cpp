#include "accel/adaptive_grid.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "accel/cell_binner.h"
#include "accel/cell_expansion.h"
#include "accel/empty_merge.h"
#include "accel/grid_fragments.h"
#include "accel/part_lists.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "shared/gpu_types.h"

namespace prism {
namespace {

// What a step to the next cell costs against one primitive test, for the split decision.
constexpr double kStepCost = 1.0;
// Splits in a row that leave some part with all the cell's primitives (see build).
constexpr uint32_t kMaxIdleSplits = 3;

// Voxels per top cell and axis: as fine as 16-bit voxel coordinates allow, at most what the
// levels can split.
uint32_t chooseShift(const glm::ivec3 &topResolution, uint32_t maxDepth) {
    int largest = std::max({topResolution.x, topResolution.y, topResolution.z});
    uint32_t shift = 0;
    while (shift < maxDepth * kAdaptiveMaxSplit && (largest << (shift + 1)) <= 65535)
        ++shift;
    return shift;
}

// A primitive's bounding box in voxels from the grid's low corner, in fixed point (1/256 of a
// voxel, rounded outwards): every level finds the parts it meets from this by a subtraction and
// a shift, with its own slack, instead of the binner's double division for every candidate.
constexpr int kVoxelFractionBits = 8;
struct VoxelBounds {
    glm::ivec3 lo, hi;
};

// Fixed-point voxel coordinates far outside the grid are clamped: the ranges clamp them anyway.
inline int toFixedVoxels(double voxels, bool roundUp) {
    double v = std::clamp(voxels, -double(1 << 17), double(1 << 17)) * (1 << kVoxelFractionBits);
    return int(roundUp ? std::ceil(v) : std::floor(v));
}

// The parts each primitive meets at every level, by bounding box.
class PartRanges {
public:
    PartRanges(const Grid &grid, double magnitude) {
        glm::dvec3 voxel(grid.voxelSize());
        for (uint32_t k = 0; k < slack_.size(); ++k) {
            // CellBinner's slack for parts of 2^k voxels, in voxels, rounded up to the fixed
            // point, and one more unit for the rounding of the bounds: so the ranges hold every
            // part the binner's would.
            glm::dvec3 slack = (1e-4 * voxel * double(1u << k) + 4e-7 * magnitude) / voxel;
            for (int a = 0; a < 3; ++a)
                slack_[k][a] = toFixedVoxels(slack[a], true) + 1;
        }
    }

    // The parts [lo, hi] of the window `parts` (cells of 2^partShift voxels) that `b` meets.
    CellRange range(const VoxelBounds &b, const Lattice &parts, uint32_t partShift) const {
        int shift = int(partShift) + kVoxelFractionBits; // >> on int floors, negatives too
        glm::ivec3 lo = (b.lo - slack_[partShift]) >> shift;
        glm::ivec3 hi = (b.hi + slack_[partShift]) >> shift;
        return {glm::clamp(lo, parts.lo, parts.hi - 1), glm::clamp(hi, parts.lo, parts.hi - 1)};
    }

private:
    std::array<glm::ivec3, 17> slack_{}; // 16-bit voxel coordinates: at most 16 halvings
};

// The split the density asks for, by the count of primitives a cell holds: parts per axis as a
// power of two, round(log2(cbrt(density * n))) in [1, kAdaptiveMaxSplit], for about density
// cells a primitive (a split into 8^d cells). The counts most cells hold are worked out once a
// build: three libm calls for every cell were 6% of a 100k-triangle build.
class SplitsByCount {
public:
    explicit SplitsByCount(double density) : density_(density) {
        for (uint32_t n = 0; n < table_.size(); ++n)
            table_[n] = uint8_t(compute(n));
    }
    uint32_t operator()(uint32_t n) const { return n < table_.size() ? table_[n] : compute(n); }

private:
    uint32_t compute(uint32_t n) const {
        double d = std::round(std::log2(std::cbrt(density_ * double(n))));
        return uint32_t(std::clamp(d, 1.0, double(kAdaptiveMaxSplit)));
    }

    double density_;
    std::array<uint8_t, 1024> table_{};
};

// What a thread builds top cells' trees with, kept across the top cells it builds: the part
// lists to sort into, one a level (a build sorts at every split it makes, and fresh lists
// allocated three vectors each time), the empty-part merge's marks, and the fragment a tree is
// built into, then copied into the top cell's own at its size (built in place, its four
// vectors grew from nothing by doubling: some thirty allocations and copies a top cell, of
// some 4,000 trees at 100k triangles).
struct TreeScratch {
    std::vector<PartLists> levels;
    std::vector<uint8_t> taken;
    Fragment fragment;

    Fragment &freshFragment() {
        fragment.entries.assign(1, 0u);
        fragment.cellBoxes.clear();
        fragment.cellCounts.clear();
        fragment.cellPrimitives.clear();
        fragment.depth = fragment.maxPerCell = 0;
        return fragment;
    }
};

// TreeScratch for every thread at work, lent to one task at a time and kept for the next
// build. Not thread_local: a thread_local with a destructor registers it at the thread's first
// use, under the dynamic loader's lock, which OpenImageIO's load holds for ~200 ms as
// prism-render starts: a 100k-triangle build that took 20 ms waited 200 for it (benchmarks.md,
// thirtieth session). Each flag on a cache line of its own, apart from the scratch its holder
// writes, as every thread takes and gives back a slot at each top cell. A process forked
// during a build finds the flags its parent's threads held set, and builds on scratch of its
// own.
class TreeScratchSlots {
public:
    // The process's: shared by builds running at once, each task taking a free slot.
    static TreeScratchSlots &shared() {
        static TreeScratchSlots slots(std::max(64u, std::thread::hardware_concurrency()));
        return slots;
    }

    // Runs work(scratch) on a scratch no other task holds meanwhile (one of its own where
    // every slot is taken).
    template <typename Work> void lend(Work work) {
        for (Slot &slot : slots_) {
            bool expected = false;
            if (!slot.busy.load(std::memory_order_relaxed) &&
                slot.busy.compare_exchange_strong(expected, true, std::memory_order_acquire)) {
                struct Release {
                    std::atomic<bool> &busy;
                    ~Release() { busy.store(false, std::memory_order_release); }
                } release{slot.busy};
                work(slot.scratch);
                return;
            }
        }
        TreeScratch own;
        work(own);
    }

private:
    explicit TreeScratchSlots(size_t slots) : slots_(slots) {}

    struct Slot {
        alignas(64) std::atomic<bool> busy{false};
        alignas(64) TreeScratch scratch;
    };
    std::vector<Slot> slots_;
};

void copyAtItsSize(const Fragment &from, Fragment &to) {
    to.entries.assign(from.entries.begin(), from.entries.end());
    to.cellBoxes.assign(from.cellBoxes.begin(), from.cellBoxes.end());
    to.cellCounts.assign(from.cellCounts.begin(), from.cellCounts.end());
    to.cellPrimitives.assign(from.cellPrimitives.begin(), from.cellPrimitives.end());
    to.depth = from.depth;
    to.maxPerCell = from.maxPerCell;
}

class Splitter {
public:
    Splitter(TreeScratch &scratch, const Grid &grid, const FinitePrimitives &primitives,
             const std::vector<VoxelBounds> &voxels, const PartRanges &ranges,
             const SplitsByCount &splits, double magnitude, size_t budget,
             const AdaptiveStyle &style)
        : out_(scratch.freshFragment()), grid_(grid), primitives_(primitives), voxels_(voxels),
          ranges_(ranges), splits_(splits), scratch_(scratch.levels), taken_(scratch.taken),
          magnitude_(magnitude), voxelSize_(glm::dvec3(grid.voxelSize())), budget_(budget),
          style_(style) {
        // Splits are made above style.maxDepth only; the buffers only grow, before any list is
        // read, so no reference into them moves.
        if (scratch_.size() < style.maxDepth)
            scratch_.resize(style.maxDepth);
    }

    // Makes entry `entry` the cell, or the tree of cells, of the box of 2^sizeShift voxels per
    // axis from voxelMin, which `refs` overlap.
    // `idleSplits`: how many splits above in a row left some part with all their primitives.
    void build(uint32_t entry, glm::ivec3 voxelMin, uint32_t sizeShift, uint32_t level,
               uint32_t idleSplits, std::span<const uint32_t> refs) {
        uint32_t n = uint32_t(refs.size());
        uint32_t split = chooseSplit(n, sizeShift, level);
        if (split == 0) {
            makeLeaf(entry, voxelMin, sizeShift, refs);
            return;
        }
        // Surface area heuristic (MacDonald & Booth 1990) for a uniform split: a ray through
        // this cell tests its n primitives; split, it steps through about 1.5 parts per axis
        // and meets each part with probability area(part) / area(cell) = 1 / parts^2. Where
        // primitives are large against the parts (overlapping spheres) a split only copies
        // references. The split the density asks for and each coarser one are priced; the
        // cheapest is made if it beats not splitting. Counts here go by bounding boxes (a
        // superset of what each part will list): exact tests are left to the leaves, where
        // they are needed, instead of being repeated at every level and candidate.
        uint32_t best = style_.costModel ? 0 : split;
        double bestCost = double(n);
        for (uint32_t d = split; d >= 1 && style_.costModel; --d) {
            double parts = double(1u << d);
            // Each ref lands in one part at least: a split whose cost with n references does
            // not beat the best is not counted (the same choice, without the counting).
            if (kStepCost * 1.5 * parts + double(n) / (parts * parts) >= bestCost)
                continue;
            double cost = kStepCost * 1.5 * parts +
                          double(referencesAfter(refs, voxelMin, sizeShift, d)) / (parts * parts);
            if (cost < bestCost) {
                bestCost = cost;
                best = d;
            }
        }
        if (best == 0 || budgetSpent()) {
            makeLeaf(entry, voxelMin, sizeShift, refs);
            return;
        }
        split = best;
        uint32_t childShift = sizeShift - split, parts = 1u << split;
        Lattice children = childLattice(voxelMin, sizeShift, split);
        // Each part's list, by bounding box. Each level's lists in its own buffer (the parts below
        // this one are built, and sorted a level down, while these lists are read), reused by the
        // level's next split.
        PartLists &childRefs = scratch_[level];
        sortIntoParts(
            children, refs,
            [&](size_t i) { return ranges_.range(voxels_[refs[i]], children, childShift); },
            childRefs);
        // A split that leaves some part with every primitive may still help further down (a
        // small cluster in a big cell), but three in a row mean the primitives cannot be told
        // apart (all in one point, a fan around one vertex): the cell stays whole. This also
        // bounds the work and the empty cells such scenes cost.
        idleSplits = childRefs.fullest >= n ? idleSplits + 1 : 0;
        if (idleSplits >= kMaxIdleSplits) {
            makeLeaf(entry, voxelMin, sizeShift, refs);
            return;
        }

        size_t first = out_.entries.size();
        if (first + children.count() > kMaxAdaptiveIndex)
            throw Error("adaptive grid needs more than 2^28 voxel-map entries; use --grid regular");
        out_.entries.resize(first + children.count());
        out_.entries[entry] = uint32_t(first) << 4 | split;
        out_.depth = std::max(out_.depth, level + 1);
        if (style_.mergeEmptyParts)
            mergeEmptyParts(uint32_t(first), children, childShift, childRefs);
        for (int z = 0; z < int(parts); ++z)
            for (int y = 0; y < int(parts); ++y)
                for (int x = 0; x < int(parts); ++x) {
                    glm::ivec3 cell = children.lo + glm::ivec3(x, y, z);
                    uint32_t local = children.local(cell);
                    std::span<const uint32_t> list = childRefs.list(local);
                    if (!style_.mergeEmptyParts || !list.empty())
                        build(uint32_t(first) + local, cell << int(childShift), childShift,
                              level + 1, idleSplits, list);
                }
    }

private:
    // The 2^split parts per axis of the cell of 2^sizeShift voxels from voxelMin.
    Lattice childLattice(glm::ivec3 voxelMin, uint32_t sizeShift, uint32_t split) const {
        uint32_t childShift = sizeShift - split;
        Lattice l;
        l.origin = glm::dvec3(grid_.boundsMin);
        l.cellSize = voxelSize_ * double(1u << childShift);
        l.lo = voxelMin >> int(childShift);
        l.hi = l.lo + glm::ivec3(1 << split);
        l.magnitude = magnitude_;
        return l;
    }

    // References over all parts of a split, by bounding box.
    size_t referencesAfter(std::span<const uint32_t> refs, glm::ivec3 voxelMin, uint32_t sizeShift,
                           uint32_t split) const {
        Lattice parts = childLattice(voxelMin, sizeShift, split);
        uint32_t partShift = sizeShift - split;
        size_t references = 0;
        for (uint32_t id : refs)
            references += ranges_.range(voxels_[id], parts, partShift).cells();
        return references;
    }

    bool budgetSpent() const { return out_.entries.size() + out_.cellBoxes.size() > budget_; }

    // Parts per axis, as a power of two (SplitsByCount), none for a cell with few primitives or
    // no levels left, and no finer than the cell's voxels.
    uint32_t chooseSplit(uint32_t n, uint32_t sizeShift, uint32_t level) const {
        if (n <= kAdaptiveLeafPrimitives || sizeShift == 0 || level >= style_.maxDepth)
            return 0;
        return std::min(splits_(n), sizeShift);
    }

    // The cell of 2^sizeShift voxels from voxelMin, listing exactly the `refs` that overlap it
    // (refs came down by bounding box: a superset). A lean grid lists them all: its one image
    // pays less for a few more tests a ray than the exact tests would cost (below).
    void makeLeaf(uint32_t entry, glm::ivec3 voxelMin, uint32_t sizeShift,
                  std::span<const uint32_t> refs) {
        if (grid_.lean) {
            // The exact tests read every listed triangle's vertices, scattered over the scene's
            // array: at a million triangles they were a third of the lean build (488 -> 303 ms
            // without them), and their lists saved 28% of the tests a ray (6.91 -> 4.98) for a
            // frame 5-11% faster (benchmarks.md, twenty-ninth session). Lists by bounding box
            // are a superset, which the walk allows: it accepts a hit only inside the cell.
            out_.cellPrimitives.insert(out_.cellPrimitives.end(), refs.begin(), refs.end());
            size_t cell =
                newCell(voxelMin, voxelMin + glm::ivec3(1 << sizeShift), uint32_t(refs.size()));
            out_.entries[entry] = uint32_t(cell) << 4;
            return;
        }
        Lattice self = childLattice(voxelMin, sizeShift, 0);
        CellBinner binner(self);
        // A primitive whose box lies inside the cell overlaps it without the exact test (most
        // of a fine cell's primitives, where a triangle's separating-axis test is the costly part
        // of a leaf). Its fixed-point box is rounded outwards, so inside the cell's own voxels
        // means inside the cell widened by the binner's slack, which the exact test would
        // confirm: the lists are the same, and no world-space box per primitive is kept for it
        // (48 bytes a primitive of fresh memory: 48 MB at a million triangles).
        glm::ivec3 cellLo = voxelMin << kVoxelFractionBits;
        glm::ivec3 cellHi = (voxelMin + glm::ivec3(1 << sizeShift)) << kVoxelFractionBits;
        auto insideCell = [&](const VoxelBounds &v) {
            return glm::all(glm::greaterThanEqual(v.lo, cellLo)) &&
                   glm::all(glm::lessThanEqual(v.hi, cellHi));
        };
        uint32_t count = 0;
        for (uint32_t id : refs)
            if (insideCell(voxels_[id]) || binner.overlaps(id, primitives_, self.lo)) {
                out_.cellPrimitives.push_back(id);
                ++count;
            }
        size_t cell = newCell(voxelMin, voxelMin + glm::ivec3(1 << sizeShift), count);
        out_.entries[entry] = uint32_t(cell) << 4;
    }

    // Makes the empty parts of a split into few cells (accel/empty_merge.h), each one cell
    // whose entries all point to it.
    void mergeEmptyParts(uint32_t first, const Lattice &parts, uint32_t childShift,
                         const PartLists &childRefs) {
        glm::ivec3 size = parts.size();
        mergeEmptyBoxes(
            size, [&](uint32_t i) { return childRefs.empty(i); },
            [&](glm::ivec3 lo, glm::ivec3 hi) {
                size_t cell = newCell((parts.lo + lo) << int(childShift),
                                      (parts.lo + hi) << int(childShift), 0);
                for (int z = lo.z; z < hi.z; ++z)
                    for (int y = lo.y; y < hi.y; ++y)
                        for (int x = lo.x; x < hi.x; ++x)
                            out_.entries[first + uint32_t(x + size.x * (y + size.y * z))] =
                                uint32_t(cell) << 4;
            },
            taken_);
    }

    // Appends a cell with the given box whose `count` primitives the caller appends.
    size_t newCell(glm::ivec3 boxMin, glm::ivec3 boxMax, uint32_t count) {
        size_t cell = out_.cellBoxes.size();
        if (cell >= kMaxAdaptiveIndex)
            throw Error("adaptive grid needs more than 2^28 cells; use --grid regular");
        out_.cellBoxes.push_back(packCellBox(boxMin, boxMax));
        out_.cellCounts.push_back(count);
        out_.maxPerCell = std::max(out_.maxPerCell, count);
        return cell;
    }

    Fragment &out_;
    const Grid &grid_;
    const FinitePrimitives &primitives_;
    const std::vector<VoxelBounds> &voxels_;
    const PartRanges &ranges_;
    const SplitsByCount &splits_;
    std::vector<PartLists> &scratch_; // by level: sized for every level a split is made at
    std::vector<uint8_t> &taken_;     // the empty-part merge's
    double magnitude_;
    glm::dvec3 voxelSize_;
    size_t budget_;
    AdaptiveStyle style_;
};

} // namespace

void buildAdaptiveCells(Grid &grid, const FinitePrimitives &primitives, const GridOptions &options,
                        const AdaptiveStyle &style) {
    grid.shift = chooseShift(grid.resolution, style.maxDepth);
    Lattice top = wholeGrid(grid);
    // Bounding boxes in voxels, computed once, in parallel: every level above the leaves bins
    // by them, as the top grid does here (sorted stably: ids ascending in a cell, as the
    // expansion's subset tests need).
    std::vector<VoxelBounds> voxels(primitives.count());
    std::vector<uint32_t> ids(primitives.count());
    glm::dvec3 origin(grid.boundsMin), voxel(grid.voxelSize());
    parallelForInBlocks(voxels.size(), 4096, [&](size_t id) {
        Aabb bounds = primitives.bounds(uint32_t(id));
        glm::dvec3 lo = (bounds.min - origin) / voxel, hi = (bounds.max - origin) / voxel;
        for (int a = 0; a < 3; ++a) {
            voxels[id].lo[a] = toFixedVoxels(lo[a], false);
            voxels[id].hi[a] = toFixedVoxels(hi[a], true);
        }
        ids[id] = uint32_t(id);
    });
    PartRanges ranges(grid, top.magnitude);
    SplitsByCount splits(double(options.density));
    PartLists topRefs = sortIntoPartsOnEveryCore(
        top, ids, [&](size_t i) { return ranges.range(voxels[i], top, grid.shift); },
        parallelThreadCount());
    ids = {};

    // Empty top cells are merged as a split's empty parts are: the first top cell of each box
    // makes the box's cell, and the others' entries point to it (grid_fragments.h). Where most
    // top cells are empty (the top grid of a large mesh has many small ones), their space is
    // then a few large cells, which the expansion grows further, instead of many cells that it
    // grows by three neighbours at most.
    std::vector<Fragment> fragments(top.count());
    std::vector<uint8_t> taken;
    if (style.mergeEmptyParts)
        mergeEmptyBoxes(
            top.size(), [&](uint32_t t) { return topRefs.empty(t); },
            [&](glm::ivec3 lo, glm::ivec3 hi) {
                uint32_t first = top.local(lo);
                fragments[first].cellBoxes.push_back(
                    packCellBox(lo << int(grid.shift), hi << int(grid.shift)));
                fragments[first].cellCounts.push_back(0);
                for (int z = lo.z; z < hi.z; ++z)
                    for (int y = lo.y; y < hi.y; ++y)
                        for (int x = lo.x; x < hi.x; ++x)
                            if (uint32_t t = top.local({x, y, z}); t != first)
                                fragments[t].sameCellAs = first;
            },
            taken);
    // Cells and entries at most ~64 per primitive a top cell holds (and a floor for small
    // cells): a safety net on memory and build time, far above what the cost model asks for.
    TreeScratchSlots &slots = TreeScratchSlots::shared();
    parallelFor(top.count(), [&](size_t t) {
        if (!fragments[t].cellBoxes.empty() || fragments[t].sameCellAs >= 0)
            return; // a merged empty top cell
        glm::ivec3 cell(int(t % uint32_t(grid.resolution.x)),
                        int(t / uint32_t(grid.resolution.x) % uint32_t(grid.resolution.y)),
                        int(t / (uint64_t(grid.resolution.x) * uint32_t(grid.resolution.y))));
        std::span<const uint32_t> refs = topRefs.list(t);
        size_t budget = 64 * refs.size() + 4096;
        slots.lend([&](TreeScratch &scratch) {
            Splitter splitter(scratch, grid, primitives, voxels, ranges, splits, top.magnitude,
                              budget, style);
            splitter.build(0, cell << int(grid.shift), grid.shift, 0, 0, refs);
            copyAtItsSize(scratch.fragment, fragments[t]);
        });
    });
    joinFragments(grid, fragments);
    if (style.expand && !grid.lean)
        expandCells(grid);
}

glm::uvec4 packCellBox(glm::ivec3 min, glm::ivec3 max) {
    auto pack = [](int lo, int hi) { return uint32_t(lo) | uint32_t(hi) << 16; };
    return {pack(min.x, min.y), pack(min.z, max.x), pack(max.y, max.z), 0u};
}

void unpackCellBox(const glm::uvec4 &packed, glm::ivec3 &min, glm::ivec3 &max) {
    min = gpu::cellBoxMin(packed); // the tracer's own reading (shared/gpu_types.h)
    max = gpu::cellBoxMax(packed);
}

} // namespace prism
