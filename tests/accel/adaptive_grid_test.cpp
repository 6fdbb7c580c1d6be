// The adaptive grid's structure: its cells tile the grid's box, the voxel map finds the cell
// that holds a voxel, each cell lists exactly the primitives overlapping its box (a lean
// grid's, those whose bounding box meets it), and it adapts to uneven scenes. (Walks against brute
// force: grid_walk_test.cpp.)
#include <algorithm>
#include <climits>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "accel/adaptive_grid.h"
#include "accel/grid.h"
#include "accel/grid_walk.h"
#include "accel/part_lists.h"
#include "core/parallel_for.h"
#include "grid_test_scenes.h"

namespace prism {
namespace {

Grid adaptive(const Scene &scene) {
    return buildGrid(scene, parseGridOption("adaptive"));
}

void expectWellFormed(const Grid &g) {
    ASSERT_TRUE(g.adaptive());
    ASSERT_EQ(g.cellStart.size(), g.cellBoxes.size() + 1);
    EXPECT_EQ(g.cellStart.front(), 0u);
    EXPECT_EQ(g.cellStart.back(), g.cellPrimitives.size());
    EXPECT_TRUE(std::is_sorted(g.cellStart.begin(), g.cellStart.end()));
    // Every box lies inside the virtual grid. (Expanded boxes overlap: the voxel map, not the
    // boxes, says which cell owns a voxel.)
    glm::ivec3 res = g.voxelResolution();
    for (const glm::uvec4 &packed : g.cellBoxes) {
        glm::ivec3 lo, hi;
        unpackCellBox(packed, lo, hi);
        ASSERT_TRUE(glm::all(glm::lessThan(lo, hi)));
        ASSERT_TRUE(glm::all(glm::greaterThanEqual(lo, glm::ivec3(0))));
        ASSERT_TRUE(glm::all(glm::lessThanEqual(hi, res)));
    }
    // The map sends random voxels to the cell whose box holds them.
    std::mt19937 rng(1);
    for (int i = 0; i < 2000; ++i) {
        glm::ivec3 v(int(rng() % uint32_t(res.x)), int(rng() % uint32_t(res.y)),
                     int(rng() % uint32_t(res.z)));
        glm::ivec3 lo, hi;
        unpackCellBox(g.cellBoxes.at(adaptiveCellAt(g, v)), lo, hi);
        ASSERT_TRUE(glm::all(glm::lessThanEqual(lo, v)) && glm::all(glm::lessThan(v, hi)));
    }
}

TEST(AdaptiveGrid, BoxesLieInTheGridAndTheMapFindsThem) {
    expectWellFormed(adaptive(test::randomSpheresAndTriangles(41, 300, 600)));
    expectWellFormed(adaptive(test::clusterInARoom(42, 2000, 100)));
    expectWellFormed(buildGrid(test::clusterInARoom(42, 2000, 100), parseGridOption("two-level")));
}

// The empty parts of a split become few cells, each the box of the map entries that point to
// it; only empty cells are shared by entries.
TEST(AdaptiveGrid, EmptyPartsOfASplitAreMerged) {
    Grid g = adaptive(test::clusterInARoom(44, 2000, 100));
    expectWellFormed(g);
    std::vector<uint32_t> entriesOf(g.cellBoxes.size(), 0);
    size_t leaves = 0;
    for (uint32_t entry : g.entries)
        if ((entry & 15u) == 0) {
            ++entriesOf[entry >> 4];
            ++leaves;
        }
    size_t shared = 0;
    for (uint32_t c = 0; c < g.cellBoxes.size(); ++c) {
        EXPECT_GE(entriesOf[c], 1u) << "every cell is in the map";
        if (entriesOf[c] > 1) {
            ++shared;
            EXPECT_EQ(g.cellStart[c + 1], g.cellStart[c]) << "only empty cells are merged";
        }
    }
    EXPECT_GT(shared, 0u);
    EXPECT_LT(g.cellBoxes.size(), leaves * 3 / 4)
        << "merging saves a quarter of the cells at least";
}

// Empty top cells are merged too: in a room with a small cluster most top cells are empty, and
// they become a few cells, each the box of the top cells whose entries point to it.
TEST(AdaptiveGrid, EmptyTopCellsAreMerged) {
    Grid g = adaptive(test::clusterInARoom(48, 2000, 100));
    expectWellFormed(g);
    std::vector<uint32_t> topEntriesOf(g.cellBoxes.size(), 0);
    size_t emptyTopCells = 0;
    for (uint32_t t = 0; t < g.topCellCount(); ++t)
        if ((g.entries[t] & 15u) == 0) {
            uint32_t cell = g.entries[t] >> 4;
            ++topEntriesOf[cell];
            emptyTopCells += g.cellStart[cell + 1] == g.cellStart[cell];
        }
    size_t mergedCells = 0;
    for (uint32_t c = 0; c < g.cellBoxes.size(); ++c)
        if (topEntriesOf[c] > 1) {
            ++mergedCells;
            EXPECT_EQ(g.cellStart[c + 1], g.cellStart[c]) << "only empty top cells are merged";
        }
    EXPECT_GT(emptyTopCells, 40u) << "of " << g.topCellCount() << " top cells";
    EXPECT_LT(mergedCells * 4, emptyTopCells) << "the empty top cells are a few cells";
}

// Each cell's box as built, before the expansion grew it: the union of the voxel-map nodes whose
// leaf entries point to the cell (a merged cell has several).
std::vector<std::pair<glm::ivec3, glm::ivec3>> builtBoxes(const Grid &g) {
    std::vector<std::pair<glm::ivec3, glm::ivec3>> boxes(g.cellBoxes.size(),
                                                         {glm::ivec3(INT_MAX), glm::ivec3(0)});
    std::function<void(uint32_t, glm::ivec3, int)> visit = [&](uint32_t index, glm::ivec3 lo,
                                                               int shift) {
        uint32_t entry = g.entries[index];
        int split = int(entry & 15u);
        if (split == 0) {
            auto &box = boxes[entry >> 4];
            box.first = glm::min(box.first, lo);
            box.second = glm::max(box.second, lo + (1 << shift));
            return;
        }
        int childShift = shift - split, parts = 1 << split;
        for (int i = 0; i < parts * parts * parts; ++i) {
            glm::ivec3 part(i % parts, i / parts % parts, i / (parts * parts));
            visit((entry >> 4) + uint32_t(i), lo + (part << childShift), childShift);
        }
    };
    for (uint32_t t = 0; t < g.topCellCount(); ++t) {
        glm::ivec3 top(int(t % uint32_t(g.resolution.x)),
                       int(t / uint32_t(g.resolution.x) % uint32_t(g.resolution.y)),
                       int(t / (uint32_t(g.resolution.x) * uint32_t(g.resolution.y))));
        visit(t, top << int(g.shift), int(g.shift));
    }
    return boxes;
}

// Every primitive is listed in each cell its (expanded) box overlaps, and a listed one overlaps
// the cell's box as built, grown by twice the binner's slack: the exact tests, not bounding
// boxes, decide (the room's walls are triangles whose bounding boxes cover whole faces).
TEST(AdaptiveGrid, CellsListExactlyTheOverlappingPrimitives) {
    Scene scene = test::clusterInARoom(43, 400, 60);
    Grid g = adaptive(scene);
    glm::dvec3 lo(g.boundsMin), voxel(g.voxelSize());
    double magnitude = std::max({std::abs(double(g.boundsMin.x)), std::abs(double(g.boundsMax.x)),
                                 std::abs(double(g.boundsMin.y)), std::abs(double(g.boundsMax.y)),
                                 std::abs(double(g.boundsMin.z)), std::abs(double(g.boundsMax.z))});
    std::vector<std::pair<glm::ivec3, glm::ivec3>> built = builtBoxes(g);
    PrimitiveIds ids(scene);
    for (uint32_t c = 0; c < g.cellBoxes.size(); ++c) {
        glm::ivec3 vmin, vmax;
        unpackCellBox(g.cellBoxes[c], vmin, vmax);
        std::vector<uint32_t> listed(g.cellPrimitives.begin() + g.cellStart[c],
                                     g.cellPrimitives.begin() + g.cellStart[c + 1]);
        test::expectCellListsExactly(scene, lo + glm::dvec3(vmin) * voxel,
                                     lo + glm::dvec3(vmax) * voxel, listed);
        glm::dvec3 builtMin = lo + glm::dvec3(built[c].first) * voxel;
        glm::dvec3 builtMax = lo + glm::dvec3(built[c].second) * voxel;
        glm::dvec3 slack = 2.0 * (1e-4 * (builtMax - builtMin) + glm::dvec3(4e-7 * magnitude));
        for (uint32_t id : listed)
            ASSERT_TRUE(test::overlapsBox(scene, ids, id, builtMin - slack, builtMax + slack))
                << "cell " << c << " lists primitive " << id << ", which misses its box as built";
        if (HasFatalFailure())
            return;
    }
}

// The shader's float walk may put a hit just outside the cell it tests, by up to the rounding
// of the coordinates: so a cell also lists what lies within the binner's slack of its box
// (4e-7 of the largest coordinate, and more). Far from the origin that slack is a few percent
// of a fine cell, and many primitives lie that close to a cell they do not overlap.
TEST(AdaptiveGrid, CellsListWhatLiesWithinTheSlack) {
    Scene scene = test::randomSpheresAndTriangles(47, 150, 300, 1.0);
    for (Sphere &s : scene.spheres)
        s.center.x += 10000.0f;
    for (Triangle &t : scene.triangles)
        for (glm::dvec3 &p : t.p)
            p.x += 10000.0;
    Grid g = adaptive(scene);
    glm::dvec3 lo(g.boundsMin), voxel(g.voxelSize());
    double magnitude = std::max(std::abs(double(g.boundsMax.x)), std::abs(double(g.boundsMin.x)));
    glm::dvec3 margin(0.9 * 4e-7 * magnitude);
    PrimitiveIds ids(scene);
    size_t withinTheSlackOnly = 0;
    for (uint32_t c = 0; c < g.cellBoxes.size(); ++c) {
        glm::ivec3 vmin, vmax;
        unpackCellBox(g.cellBoxes[c], vmin, vmax);
        glm::dvec3 boxMin = lo + glm::dvec3(vmin) * voxel, boxMax = lo + glm::dvec3(vmax) * voxel;
        auto first = g.cellPrimitives.begin() + g.cellStart[c];
        auto last = g.cellPrimitives.begin() + g.cellStart[c + 1];
        for (uint32_t id = 0; id < ids.count(); ++id) {
            if (!test::overlapsBox(scene, ids, id, boxMin - margin, boxMax + margin))
                continue;
            withinTheSlackOnly += !test::overlapsBox(scene, ids, id, boxMin, boxMax);
            ASSERT_TRUE(std::binary_search(first, last, id))
                << "primitive " << id << " within the slack of cell " << c << " is not listed";
        }
    }
    EXPECT_GT(withinTheSlackOnly, 40u) << "the scene puts primitives within the slack of cells";
}

// A cluster 500 times smaller than its room still gets cells of its own size: its fullest
// cell holds a few primitives, where one regular grid of the same budget holds hundreds.
TEST(AdaptiveGrid, FollowsAClusterInARoom) {
    Scene scene = test::clusterInARoom(44, 3000, 0);
    Grid regular = buildGrid(scene, parseGridOption("regular"));
    Grid g = adaptive(scene);
    expectWellFormed(g);
    EXPECT_GT(regular.maxPerCell, 500u);
    EXPECT_LT(g.maxPerCell, regular.maxPerCell / 10);
    EXPECT_LT(g.cellBoxes.size(), 40 * scene.triangles.size()) << "memory stays linear";
}

// Built lean (GridOptions::effort), the adaptive grid is the full one's voxel map with each
// cell's box as built: the boxes tile the grid. The expansion only grows boxes.
TEST(AdaptiveGrid, LeanCellsKeepTheirBuiltBoxes) {
    Scene scene = test::clusterInARoom(48, 600, 40);
    GridOptions lean = parseGridOption("adaptive");
    lean.effort = GridOptions::Effort::Lean;
    Grid g = buildGrid(scene, lean), expanded = adaptive(scene);
    expectWellFormed(g);
    EXPECT_TRUE(g.lean);
    EXPECT_FALSE(expanded.lean);
    EXPECT_EQ(g.entries, expanded.entries);
    std::vector<std::pair<glm::ivec3, glm::ivec3>> built = builtBoxes(g);
    uint64_t volume = 0;
    size_t grown = 0;
    for (uint32_t c = 0; c < g.cellBoxes.size(); ++c) {
        glm::ivec3 lo, hi;
        unpackCellBox(g.cellBoxes[c], lo, hi);
        ASSERT_EQ(lo, built[c].first) << "cell " << c;
        ASSERT_EQ(hi, built[c].second) << "cell " << c;
        glm::ivec3 size = hi - lo;
        volume += uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z);
        grown += g.cellBoxes[c] != expanded.cellBoxes[c];
    }
    glm::ivec3 res = g.voxelResolution();
    EXPECT_EQ(volume, uint64_t(res.x) * uint64_t(res.y) * uint64_t(res.z)) << "boxes tile the grid";
    EXPECT_GT(grown, g.cellBoxes.size() / 4) << "the expanded grid grew many of them";
}

// A lean grid's leaves list their primitives by bounding box, without the exact tests: each
// lists what the full grid's cell lists (every primitive that overlaps it) and more, and only
// primitives whose bounding box meets the cell's box grown by twice the slack of a top cell
// (a level hands each part what its own ranges, with their slack, found for the parent) and
// the levels' fixed-point rounding (bounds rounded outwards to 1/256 of a voxel, one unit more).
TEST(AdaptiveGrid, LeanCellsListByBoundingBox) {
    Scene scene = test::clusterInARoom(49, 600, 40); // walls whose boxes cover whole faces
    GridOptions lean = parseGridOption("adaptive");
    lean.effort = GridOptions::Effort::Lean;
    GridOptions full = parseGridOption("adaptive");
    full.effort = GridOptions::Effort::Full;
    Grid g = buildGrid(scene, lean), exact = buildGrid(scene, full);
    ASSERT_EQ(g.cellBoxes.size(), exact.cellBoxes.size()) << "the same cells";
    FinitePrimitives primitives(scene);
    glm::dvec3 lo(g.boundsMin), voxel(g.voxelSize());
    double magnitude = std::max({std::abs(double(g.boundsMin.x)), std::abs(double(g.boundsMax.x)),
                                 std::abs(double(g.boundsMin.y)), std::abs(double(g.boundsMax.y)),
                                 std::abs(double(g.boundsMin.z)), std::abs(double(g.boundsMax.z))});
    size_t more = 0;
    for (uint32_t c = 0; c < g.cellBoxes.size(); ++c) {
        auto first = g.cellPrimitives.begin() + g.cellStart[c];
        auto last = g.cellPrimitives.begin() + g.cellStart[c + 1];
        ASSERT_TRUE(std::is_sorted(first, last)) << "cell " << c;
        auto exactFirst = exact.cellPrimitives.begin() + exact.cellStart[c];
        auto exactLast = exact.cellPrimitives.begin() + exact.cellStart[c + 1];
        ASSERT_TRUE(std::includes(first, last, exactFirst, exactLast))
            << "cell " << c << " lacks a primitive that overlaps it";
        more += size_t(last - first) - size_t(exactLast - exactFirst);
        glm::ivec3 vmin, vmax;
        unpackCellBox(g.cellBoxes[c], vmin, vmax);
        glm::dvec3 boxMin = lo + glm::dvec3(vmin) * voxel, boxMax = lo + glm::dvec3(vmax) * voxel;
        glm::dvec3 topCell = voxel * double(1u << g.shift);
        glm::dvec3 slack =
            2.0 * (1e-4 * topCell + glm::dvec3(4e-7 * magnitude)) + 3.0 / 256.0 * voxel;
        for (auto it = first; it != last; ++it) {
            Aabb b = primitives.bounds(*it);
            ASSERT_TRUE(glm::all(glm::lessThanEqual(b.min, boxMax + slack)) &&
                        glm::all(glm::greaterThanEqual(b.max, boxMin - slack)))
                << "cell " << c << " lists primitive " << *it << ", whose box misses it";
        }
    }
    EXPECT_GT(more, 0u) << "the walls' bounding boxes put them in cells they do not overlap";
}

// Expanded cells take a ray across empty space in few steps: fewer than the cells the voxel
// map puts along its path (the walk's count without expansion).
TEST(AdaptiveGrid, ExpandedCellsCrossEmptySpaceInFewSteps) {
    Scene scene = test::clusterInARoom(47, 1000, 0);
    Grid g = adaptive(scene);
    glm::dvec3 origin(-450.0, 200.0, -300.0), dir(1.0, 0.0, 0.0);
    double length = 900.0;
    int visited = 0;
    walkGrid(g, origin, dir, length, [&](uint32_t, double, double) { return ++visited, true; });
    int mapCells = 0;
    uint32_t previous = ~0u;
    glm::dvec3 lo(g.boundsMin), voxel(g.voxelSize());
    for (int i = 0; i <= 100000; ++i) {
        glm::dvec3 p = origin + (length * i / 100000.0) * dir;
        uint32_t cell = adaptiveCellAt(g, glm::ivec3(glm::floor((p - lo) / voxel)));
        mapCells += cell != previous;
        previous = cell;
    }
    EXPECT_GT(visited, 0);
    EXPECT_LT(visited, mapCells);
}

// The same input gives the same arrays on every run and at every thread count: top cells,
// fragments and expansion blocks go to whichever thread is free.
TEST(AdaptiveGrid, BuildIsDeterministic) {
    Scene scene = test::clusterInARoom(45, 800, 80);
    Grid a = adaptive(scene), b = adaptive(scene);
    test::expectSameGrid(a, b);
    Grid twoLevel = buildGrid(scene, parseGridOption("two-level"));
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        ParallelThreads limit(threads);
        SCOPED_TRACE(threads);
        test::expectSameGrid(a, adaptive(scene));
        test::expectSameGrid(twoLevel, buildGrid(scene, parseGridOption("two-level")));
    }
}

// A scene big enough that the top cells are sorted in runs on every core and the trees' arrays
// appended on several threads (grid_fragments.cpp): the same arrays, full and lean, at every
// thread count.
TEST(AdaptiveGrid, ALargeBuildIsTheSameAtEveryThreadCount) {
    Scene scene = test::clusterInARoom(46, 30'000, 200);
    GridOptions full = parseGridOption("adaptive"), lean = full;
    lean.effort = GridOptions::Effort::Lean;
    Grid one, oneLean;
    {
        ParallelThreads limit(1);
        one = buildGrid(scene, full);
        oneLean = buildGrid(scene, lean);
    }
    ASSERT_GT(one.cellBoxes.size() + one.cellPrimitives.size(), 65'536u);
    ASSERT_TRUE(oneLean.lean);
    for (unsigned threads : {2u, 3u, 8u}) {
        ParallelThreads limit(threads);
        SCOPED_TRACE(threads);
        test::expectSameGrid(one, buildGrid(scene, full));
        test::expectSameGrid(oneLean, buildGrid(scene, lean));
    }
}

// The sort in runs on every core lists what the serial sort lists, in the same order, however
// many runs: references that meet one part or several, parts that stay empty.
TEST(PartLists, SortedOnEveryCoreAsInOne) {
    Lattice parts;
    parts.lo = glm::ivec3(0);
    parts.hi = glm::ivec3(7, 5, 3);
    std::mt19937 rng(11);
    std::vector<CellRange> ranges;
    for (int i = 0; i < 5000; ++i) {
        glm::ivec3 lo(int(rng() % 7), int(rng() % 5), int(rng() % 3));
        glm::ivec3 hi = glm::min(lo + glm::ivec3(int(rng() % 3)), parts.hi - 1);
        ranges.push_back({lo, hi});
    }
    std::vector<uint32_t> refs(ranges.size());
    for (uint32_t i = 0; i < refs.size(); ++i)
        refs[i] = 3 * i + 1;
    auto rangeOf = [&](size_t i) { return ranges[i]; };
    PartLists serial = sortIntoParts(parts, refs, rangeOf);
    for (size_t shares : {1u, 2u, 3u, 7u}) {
        for (unsigned threads : {1u, 2u}) {
            ParallelThreads limit(threads);
            PartLists lists = sortIntoPartsOnEveryCore(parts, refs, rangeOf, shares);
            EXPECT_EQ(lists.start, serial.start) << shares << " runs";
            EXPECT_EQ(lists.refs, serial.refs) << shares << " runs";
            EXPECT_EQ(lists.fullest, serial.fullest) << shares << " runs";
        }
    }
}

TEST(AdaptiveGrid, EmptySingleAndDegenerateScenes) {
    Scene empty;
    Grid g = adaptive(empty);
    expectWellFormed(g);
    EXPECT_TRUE(g.cellPrimitives.empty());

    Scene one;
    one.spheres.push_back(Sphere{{1, 2, 3}, 0.5f, 0});
    g = adaptive(one);
    expectWellFormed(g);
    EXPECT_EQ(g.maxPerCell, 1u);

    // Every primitive in one point, and degenerate triangles (a point, a segment): splitting
    // cannot separate them, so the levels run out and the build still ends.
    Scene point;
    for (int i = 0; i < 50; ++i) {
        point.spheres.push_back(Sphere{{0, 0, 0}, 1e-3f, 0});
        Triangle t;
        t.p[0] = t.p[1] = t.p[2] = glm::vec3(0.0f);
        if (i % 2)
            t.p[2] = glm::vec3(1e-3f, 0.0f, 0.0f);
        point.triangles.push_back(t);
    }
    g = adaptive(point);
    expectWellFormed(g);
    EXPECT_LE(g.depth, kAdaptiveMaxDepth);
    EXPECT_EQ(g.maxPerCell, 100u);
}

// Huge and tiny scales behave alike: the structure depends on the shape, not the units.
TEST(AdaptiveGrid, SameCellsAtAnyScale) {
    Scene scene = test::clusterInARoom(46, 300, 30, 100.0, 2.0);
    Grid reference = adaptive(scene);
    for (float scale : {1e-3f, 1e3f}) {
        Scene scaled = scene;
        for (Sphere &s : scaled.spheres) {
            s.center *= scale;
            s.radius *= scale;
        }
        for (Triangle &t : scaled.triangles)
            for (glm::dvec3 &p : t.p)
                p *= scale;
        Grid g = adaptive(scaled);
        expectWellFormed(g);
        EXPECT_EQ(g.cellBoxes.size(), reference.cellBoxes.size()) << scale;
        EXPECT_EQ(g.maxPerCell, reference.maxPerCell) << scale;
    }
}

} // namespace
} // namespace prism
