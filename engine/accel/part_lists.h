#pragma once
// Sorting references into the parts of a lattice by the range of parts each one meets: a
// counting sort into one array (no list per part), stable, so references keep their order
// within a part. The adaptive grid bins its top cells and every split this way.
#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "accel/cell_binner.h"
#include "core/parallel_for.h"

namespace prism {

// The cells [lo, hi] (inclusive) of a lattice that a primitive's bounding box meets.
struct CellRange {
    glm::ivec3 lo, hi;
    size_t cells() const {
        glm::ivec3 span = hi - lo + 1;
        return size_t(span.x) * size_t(span.y) * size_t(span.z);
    }
};

// Part p of a lattice lists refs[start[p] .. start[p + 1]).
struct PartLists {
    std::vector<uint32_t> start, refs;
    size_t fullest = 0;           // the longest list
    std::vector<uint32_t> cursor; // the sort's, kept with its capacity for the next sort

    std::span<const uint32_t> list(size_t part) const {
        return {refs.data() + start[part], start[part + 1] - start[part]};
    }
    bool empty(size_t part) const { return start[part + 1] == start[part]; }
};

// visit(i, part) for each i in [first, last) and each part of `parts` in rangeOf(i), in order:
// both sorts' passes.
template <typename RangeOf, typename Visit>
void forEachPartMet(const Lattice &parts, size_t first, size_t last, RangeOf &rangeOf,
                    Visit visit) {
    for (size_t i = first; i < last; ++i) {
        const CellRange r = rangeOf(i);
        for (int z = r.lo.z; z <= r.hi.z; ++z)
            for (int y = r.lo.y; y <= r.hi.y; ++y)
                for (int x = r.lo.x; x <= r.hi.x; ++x)
                    visit(i, parts.local({x, y, z}));
    }
}

// refs[i] goes to every part of `parts` in rangeOf(i) (a CellRange), into `lists`, whose
// vectors keep their capacity (a build sorts at every split; reused lists allocate no more).
template <typename RangeOf>
void sortIntoParts(const Lattice &parts, std::span<const uint32_t> refs, RangeOf rangeOf,
                   PartLists &lists) {
    auto forEachPart = [&](auto visit) { forEachPartMet(parts, 0, refs.size(), rangeOf, visit); };
    lists.fullest = 0;
    lists.start.assign(size_t(parts.count()) + 1, 0u);
    forEachPart([&](size_t, uint32_t part) { ++lists.start[part + 1]; });
    for (size_t part = 0; part < parts.count(); ++part) {
        lists.fullest = std::max<size_t>(lists.fullest, lists.start[part + 1]);
        lists.start[part + 1] += lists.start[part];
    }
    lists.refs.resize(lists.start.back());
    lists.cursor.assign(lists.start.begin(), lists.start.end() - 1);
    forEachPart([&](size_t i, uint32_t part) { lists.refs[lists.cursor[part]++] = refs[i]; });
}

template <typename RangeOf>
PartLists sortIntoParts(const Lattice &parts, std::span<const uint32_t> refs, RangeOf rangeOf) {
    PartLists lists;
    sortIntoParts(parts, refs, rangeOf, lists);
    return lists;
}

// The same lists, sorted on every core (parallelFor): each of `shares` consecutive runs of refs
// is counted and placed by one thread, a run's references after the runs before it in each
// part, so the lists are the serial sort's whatever the threads. For one large sort (the top
// grid's: 2 of a 100k-triangle lean build's 25 ms on one thread).
template <typename RangeOf>
PartLists sortIntoPartsOnEveryCore(const Lattice &parts, std::span<const uint32_t> refs,
                                   RangeOf rangeOf, size_t shares) {
    size_t partCount = size_t(parts.count());
    // Each run counts into an array of every part: no more runs than refs fill a part's worth
    // of them, so the counts stay under the refs' own size whatever the cores.
    shares = std::max<size_t>(1, std::min(shares, refs.size() / std::max<size_t>(1, partCount)));
    // Run `share` of the refs.
    auto forEachPart = [&](size_t share, auto visit) {
        forEachPartMet(parts, refs.size() * share / shares, refs.size() * (share + 1) / shares,
                       rangeOf, visit);
    };
    // cursors[share][part]: first a run's count in the part, then where it writes there.
    std::vector<std::vector<uint32_t>> cursors(shares);
    parallelFor(shares, [&](size_t share) {
        cursors[share].assign(partCount, 0u);
        forEachPart(share, [&](size_t, uint32_t part) { ++cursors[share][part]; });
    });
    PartLists lists;
    lists.start.resize(partCount + 1);
    uint32_t next = 0;
    for (size_t part = 0; part < partCount; ++part) {
        lists.start[part] = next;
        for (size_t share = 0; share < shares; ++share)
            next += std::exchange(cursors[share][part], next);
        lists.fullest = std::max<size_t>(lists.fullest, next - lists.start[part]);
    }
    lists.start[partCount] = next;
    lists.refs.resize(next);
    parallelFor(shares, [&](size_t share) {
        forEachPart(share,
                    [&](size_t i, uint32_t part) { lists.refs[cursors[share][part]++] = refs[i]; });
    });
    return lists;
}

} // namespace prism
