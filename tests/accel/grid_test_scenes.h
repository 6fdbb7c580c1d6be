#pragma once
// Random scenes of spheres and triangles for the grid tests.
#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accel/grid.h"
#include "accel/overlap_tests.h"
#include "scene/primitive_ids.h"
#include "scene/scene.h"

namespace prism::test {

inline Scene randomSpheresAndTriangles(unsigned seed, int spheres, int triangles,
                                       double size = 10.0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coord(-size, size), unit(0.0, 1.0);
    Scene scene;
    for (int i = 0; i < spheres; ++i) {
        Sphere s;
        s.center = glm::vec3(coord(rng), coord(rng), coord(rng));
        s.radius = float(size * (0.01 + 0.1 * unit(rng)));
        scene.spheres.push_back(s);
    }
    for (int i = 0; i < triangles; ++i) {
        Triangle t;
        glm::dvec3 base(coord(rng), coord(rng), coord(rng));
        double extent = size * (unit(rng) < 0.1 ? 1.0 : 0.15); // a few large ones
        for (glm::dvec3 &p : t.p)
            p = glm::dvec3(glm::vec3(
                base + extent * glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5)));
        scene.triangles.push_back(t);
    }
    return scene;
}

// A small dense cluster in a large, sparse room: the case one regular grid handles badly (the
// room sets the cell size, the cluster falls into a few cells). Room walls are a few huge
// triangles, the cluster hundreds of tiny ones and spheres, `clusterSize` across, at the centre.
inline Scene clusterInARoom(unsigned seed, int clusterTriangles, int clusterSpheres,
                            double roomSize = 1000.0, double clusterSize = 2.0) {
    Scene scene =
        randomSpheresAndTriangles(seed, clusterSpheres, clusterTriangles, clusterSize / 2.0);
    float r = float(roomSize / 2.0);
    glm::vec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = glm::vec3(i & 1 ? r : -r, i & 2 ? r : -r, i & 4 ? r : -r);
    int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                       {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (auto &f : faces)
        for (auto [a, b, d] : {std::array{f[0], f[1], f[2]}, std::array{f[0], f[2], f[3]}}) {
            Triangle t;
            t.p[0] = c[a];
            t.p[1] = c[b];
            t.p[2] = c[d];
            scene.triangles.push_back(t);
        }
    return scene;
}

// A few huge triangles among many tiny ones: long, thin shards on the slant through a dense
// cluster of tiny triangles and spheres, `size` across, each shard from beyond one side of the
// cluster to beyond the other, so that it crosses every cell along its path at every level.
inline Scene shardsThroughACluster(unsigned seed, int clusterTriangles, int shards,
                                   double size = 2.0) {
    Scene scene =
        randomSpheresAndTriangles(seed, clusterTriangles / 10, clusterTriangles, size / 2.0);
    std::mt19937 rng(seed + 1000);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < shards; ++i) {
        glm::dvec3 from(unit(rng), unit(rng), unit(rng)), to(unit(rng), unit(rng), unit(rng));
        from = 1.5 * size * glm::normalize(from);
        to = -1.5 * size * glm::normalize(from + 0.5 * to); // the far side, not straight across
        glm::dvec3 width = 0.01 * size * glm::normalize(glm::dvec3(unit(rng), unit(rng), 1.0));
        Triangle t;
        t.p[0] = glm::dvec3(glm::vec3(from - width));
        t.p[1] = glm::dvec3(glm::vec3(to));
        t.p[2] = glm::dvec3(glm::vec3(from + width));
        scene.triangles.push_back(t);
    }
    return scene;
}

// Checks one cell's list against its box: every primitive that overlaps the box is listed, and
// a listed one overlaps the box grown by 1% (the binner's slack is far smaller).
// Whether primitive `id` (a sphere or a triangle) overlaps the box [a, b].
inline bool overlapsBox(const Scene &scene, const PrimitiveIds &ids, uint32_t id,
                        const glm::dvec3 &a, const glm::dvec3 &b) {
    PrimitiveIds::Decoded p = ids.decode(id);
    if (p.kind == gpu::kKindSphere) {
        const Sphere &s = scene.spheres[p.index];
        return sphereOverlapsBox(s.center, s.radius, a, b);
    }
    const Triangle &t = scene.triangles[p.index];
    return triangleOverlapsBox(t.p[0], t.p[1], t.p[2], a, b);
}

inline void expectCellListsExactly(const Scene &scene, const glm::dvec3 &lo, const glm::dvec3 &hi,
                                   const std::vector<uint32_t> &listed) {
    PrimitiveIds ids(scene);
    glm::dvec3 wide = 0.01 * (hi - lo);
    auto overlaps = [&](uint32_t id, glm::dvec3 a, glm::dvec3 b) {
        return overlapsBox(scene, ids, id, a, b);
    };
    EXPECT_TRUE(std::is_sorted(listed.begin(), listed.end()));
    for (uint32_t id = 0; id < ids.count(); ++id) {
        bool isListed = std::find(listed.begin(), listed.end(), id) != listed.end();
        if (overlaps(id, lo, hi)) {
            ASSERT_TRUE(isListed) << "primitive " << id << " missing from its cell";
        }
        if (isListed) {
            ASSERT_TRUE(overlaps(id, lo - wide, hi + wide))
                << "primitive " << id << " listed far from its cell";
        }
    }
}

// Every array and field of two grids, their prototypes' grids included.
inline void expectSameGrid(const Grid &a, const Grid &b) {
    EXPECT_EQ(a.boundsMin, b.boundsMin);
    EXPECT_EQ(a.boundsMax, b.boundsMax);
    EXPECT_EQ(a.resolution, b.resolution);
    EXPECT_EQ(a.cellSize, b.cellSize);
    EXPECT_EQ(a.cellStart, b.cellStart);
    EXPECT_EQ(a.cellPrimitives, b.cellPrimitives);
    EXPECT_EQ(a.shift, b.shift);
    EXPECT_EQ(a.entries, b.entries);
    EXPECT_EQ(a.cellBoxes, b.cellBoxes);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.lean, b.lean);
    EXPECT_EQ(a.maxPerCell, b.maxPerCell);
    EXPECT_EQ(a.choice, b.choice);
    ASSERT_EQ(a.meshGrids.size(), b.meshGrids.size());
    for (size_t m = 0; m < a.meshGrids.size(); ++m)
        expectSameGrid(a.meshGrids[m], b.meshGrids[m]);
}

} // namespace prism::test
