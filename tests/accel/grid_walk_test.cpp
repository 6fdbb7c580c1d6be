// Grid traversal finds exactly what brute force finds: every place a ray meets a primitive
// lies in a cell the 3D-DDA visits, within that cell's t-range, and that cell lists it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "accel/grid.h"
#include "accel/grid_walk.h"
#include "grid_test_scenes.h"

namespace prism {
namespace {

struct Crossing {
    double t;
    uint32_t id;
};

// Every t > 0 where the ray meets a primitive (both sphere roots), brute force over all.
std::vector<Crossing> allCrossings(const Scene &scene, glm::dvec3 o, glm::dvec3 d) {
    std::vector<Crossing> out;
    uint32_t id = 0;
    for (const Sphere &s : scene.spheres) {
        glm::dvec3 oc = o - glm::dvec3(s.center);
        double b = glm::dot(oc, d), c = glm::dot(oc, oc) - double(s.radius) * s.radius;
        double disc = b * b - c;
        if (disc >= 0.0)
            for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)})
                if (t > 0.0)
                    out.push_back({t, id});
        ++id;
    }
    for (const Triangle &tri : scene.triangles) {
        // Moeller & Trumbore 1997, in double.
        glm::dvec3 p0(tri.p[0]), e1 = glm::dvec3(tri.p[1]) - p0, e2 = glm::dvec3(tri.p[2]) - p0;
        glm::dvec3 pv = glm::cross(d, e2);
        double det = glm::dot(e1, pv);
        if (det != 0.0) {
            glm::dvec3 tv = o - p0;
            double u = glm::dot(tv, pv) / det;
            glm::dvec3 qv = glm::cross(tv, e1);
            double v = glm::dot(d, qv) / det, t = glm::dot(e2, qv) / det;
            if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0)
                out.push_back({t, id});
        }
        ++id;
    }
    return out;
}

struct Visited {
    uint32_t cell;
    double tEnter, tExit;
};

std::vector<Visited> walk(const Grid &g, glm::dvec3 o, glm::dvec3 d) {
    std::vector<Visited> cells;
    walkGrid(g, o, d, std::numeric_limits<double>::infinity(), [&](uint32_t c, double a, double b) {
        cells.push_back({c, a, b});
        return true;
    });
    return cells;
}

bool listed(const Grid &g, uint32_t cell, uint32_t id) {
    auto first = g.cellPrimitives.begin() + g.cellStart[cell];
    auto last = g.cellPrimitives.begin() + g.cellStart[cell + 1];
    return std::find(first, last, id) != last;
}

glm::dvec3 randomDirection(std::mt19937 &rng) {
    std::normal_distribution<double> n;
    glm::dvec3 d;
    do
        d = {n(rng), n(rng), n(rng)};
    while (glm::length(d) < 1e-6);
    return glm::normalize(d);
}

// Rays from random origins within `span` of the origin, in random directions, or, where `aims`
// has points, towards them in turn.
void checkRays(const Scene &scene, const Grid &g, unsigned seed, int rays, double span = 14.0,
               const std::vector<glm::dvec3> &aims = {}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coord(-span, span);
    int crossingsChecked = 0;
    for (int r = 0; r < rays; ++r) {
        glm::dvec3 o(coord(rng), coord(rng), coord(rng)), d = randomDirection(rng);
        if (!aims.empty() && glm::length(aims[r % aims.size()] - o) > 1e-9)
            d = glm::normalize(aims[r % aims.size()] - o);
        if (r % 7 == 0) // axis-aligned rays exercise the zero-step axes
            d = glm::dvec3(0.0), d[r % 3] = (r % 2) ? 1.0 : -1.0;
        std::vector<Visited> cells = walk(g, o, d);
        // The walk is a connected sequence of cells with increasing, abutting t-ranges.
        for (size_t i = 0; i + 1 < cells.size(); ++i) {
            ASSERT_LE(cells[i].tEnter, cells[i].tExit);
            ASSERT_NEAR(cells[i].tExit, cells[i + 1].tEnter, 1e-9 * (1.0 + cells[i].tExit));
        }
        for (const Crossing &c : allCrossings(scene, o, d)) {
            double tol = 1e-7 * (1.0 + c.t);
            bool found = false;
            for (const Visited &v : cells)
                found = found ||
                        (c.t >= v.tEnter - tol && c.t <= v.tExit + tol && listed(g, v.cell, c.id));
            ASSERT_TRUE(found) << "ray " << r << ": primitive " << c.id << " at t=" << c.t
                               << " not in any visited cell";
            ++crossingsChecked;
        }
        // Closest hit through the grid (accept a hit once the walk has reached its cell), as
        // the shader does, equals the brute-force closest hit.
        std::vector<Crossing> all = allCrossings(scene, o, d);
        auto nearest = std::min_element(all.begin(), all.end(),
                                        [](Crossing a, Crossing b) { return a.t < b.t; });
        double best = std::numeric_limits<double>::infinity();
        walkGrid(g, o, d, best, [&](uint32_t cell, double, double tExit) {
            for (const Crossing &c : all)
                if (listed(g, cell, c.id))
                    best = std::min(best, c.t);
            return best > tExit;
        });
        if (nearest == all.end())
            EXPECT_TRUE(std::isinf(best));
        else
            EXPECT_EQ(best, nearest->t) << "ray " << r;
    }
    EXPECT_GT(crossingsChecked, rays / 10); // the rays did meet primitives
}

TEST(GridWalk, FindsEveryCrossingOnRandomRaysAutoGrid) {
    Scene scene = test::randomSpheresAndTriangles(21, 200, 400);
    checkRays(scene, buildGrid(scene), 1, 3000);
}

TEST(GridWalk, FindsEveryCrossingOnRandomRaysAnisotropicGrid) {
    Scene scene = test::randomSpheresAndTriangles(22, 100, 300);
    checkRays(scene, buildGrid(scene, parseGridOption("17x3x29")), 2, 3000);
}

TEST(GridWalk, FindsEveryCrossingInAFlatScene) {
    Scene scene = test::randomSpheresAndTriangles(23, 0, 500);
    for (Triangle &t : scene.triangles)
        for (glm::dvec3 &p : t.p)
            p.y = 0.25; // every triangle in one plane: a 2D grid
    Grid g = buildGrid(scene, parseGridOption("regular"));
    EXPECT_EQ(g.resolution.y, 1);
    checkRays(scene, g, 3, 3000);
}

TEST(GridWalk, StartsInsideTheGridAtTheOriginsCell) {
    Scene scene = test::randomSpheresAndTriangles(24, 50, 0);
    Grid g = buildGrid(scene, parseGridOption("10"));
    glm::dvec3 centre = 0.5 * (glm::dvec3(g.boundsMin) + glm::dvec3(g.boundsMax));
    std::vector<Visited> cells = walk(g, centre, {1.0, 0.0, 0.0});
    ASSERT_EQ(cells.size(), 5u); // from the middle to the +x face of a 10-cell row
    EXPECT_EQ(cells.front().cell, g.cellIndex({5, 5, 5}));
    EXPECT_EQ(cells.front().tEnter, 0.0);
}

TEST(AdaptiveGridWalk, FindsEveryCrossingOnRandomRays) {
    Scene scene = test::randomSpheresAndTriangles(31, 200, 400);
    Grid g = buildGrid(scene, parseGridOption("adaptive"));
    ASSERT_TRUE(g.adaptive());
    checkRays(scene, g, 4, 3000);
}

// Rays from inside the cluster, inside the room and outside it; the cluster is 500 times
// smaller than the room, so its cells are several levels down.
// The two-level grid (one split, no merge, no expansion) takes the same walk.
TEST(AdaptiveGridWalk, TwoLevelGridFindsEveryCrossing) {
    Scene scene = test::clusterInARoom(34, 600, 100);
    Grid g = buildGrid(scene, parseGridOption("two-level"));
    EXPECT_TRUE(g.adaptive());
    EXPECT_EQ(g.depth, 1u) << "one level below the top grid";
    checkRays(scene, g, 5, 1500, 1.5);
    checkRays(scene, g, 6, 1500, 700.0);
}

TEST(AdaptiveGridWalk, FindsEveryCrossingInAClusterInARoom) {
    Scene scene = test::clusterInARoom(32, 600, 100);
    Grid g = buildGrid(scene, parseGridOption("adaptive"));
    EXPECT_GE(g.depth, 2u) << "the cluster is split below the top grid";
    checkRays(scene, g, 5, 1500, 1.5);   // from within the cluster
    checkRays(scene, g, 6, 1500, 700.0); // from anywhere in and around the room
}

// A lean grid's leaves list by bounding box (more than what overlaps them): the walk still
// finds every crossing and the closest hit, since it accepts a hit once it has reached its cell.
TEST(AdaptiveGridWalk, LeanGridFindsEveryCrossing) {
    GridOptions lean = parseGridOption("adaptive");
    lean.effort = GridOptions::Effort::Lean;
    Scene room = test::clusterInARoom(36, 600, 100);
    Grid g = buildGrid(room, lean);
    ASSERT_TRUE(g.lean);
    checkRays(room, g, 7, 1500, 1.5);
    checkRays(room, g, 8, 1500, 700.0);
    Scene random = test::randomSpheresAndTriangles(37, 200, 400);
    checkRays(random, buildGrid(random, lean), 9, 3000);
}

// Shards: a few triangles as long as the scene, thin and on the slant, through a cluster of
// tiny ones; they sit in every leaf along their paths, beside the cluster's triangles.
TEST(AdaptiveGridWalk, FindsEveryCrossingAmongHugeAndTinyTriangles) {
    const int shards = 6;
    Scene scene = test::shardsThroughACluster(35, 1500, shards);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::dvec3> onShards; // points on the shards, to aim rays at
    for (int i = 0; i < 200; ++i) {
        const Triangle &t = scene.triangles[scene.triangles.size() - 1 - i % shards];
        double u = unit(rng), v = unit(rng) * (1.0 - u);
        onShards.push_back((1.0 - u - v) * t.p[0] + u * t.p[1] + v * t.p[2]);
    }
    for (const char *option : {"adaptive", "regular"}) {
        Grid g = buildGrid(scene, parseGridOption(option));
        EXPECT_TRUE(std::string(option) == "regular" || g.depth >= 2u) << "the cluster is split";
        checkRays(scene, g, 7, 1500, 1.0);           // from within the cluster
        checkRays(scene, g, 8, 1500, 4.0, onShards); // at the shards, from in and around it
    }
}

// Axis-parallel rays that run exactly along voxel faces and start on them.
TEST(AdaptiveGridWalk, FindsEveryCrossingAlongCellFaces) {
    Scene scene = test::clusterInARoom(33, 300, 50);
    Grid g = buildGrid(scene, parseGridOption("adaptive"));
    glm::dvec3 lo(g.boundsMin), voxel(g.voxelSize());
    std::mt19937 rng(7);
    glm::ivec3 res = g.voxelResolution();
    int crossings = 0;
    for (int r = 0; r < 600; ++r) {
        glm::ivec3 v(int(rng() % uint32_t(res.x)), int(rng() % uint32_t(res.y)),
                     int(rng() % uint32_t(res.z)));
        glm::dvec3 o = lo + glm::dvec3(v) * voxel; // a voxel corner: on three faces
        glm::dvec3 d(0.0);
        d[r % 3] = (r / 3) % 2 ? 1.0 : -1.0;
        std::vector<Visited> cells = walk(g, o, d);
        for (const Crossing &c : allCrossings(scene, o, d)) {
            double tol = 1e-7 * (1.0 + c.t);
            bool found = false;
            for (const Visited &visited : cells)
                found = found || (c.t >= visited.tEnter - tol && c.t <= visited.tExit + tol &&
                                  listed(g, visited.cell, c.id));
            ASSERT_TRUE(found) << "ray " << r << ": primitive " << c.id << " at t=" << c.t;
            ++crossings;
        }
    }
    EXPECT_GT(crossings, 10);
}

TEST(GridWalk, MissingRayVisitsNothing) {
    Scene scene = test::randomSpheresAndTriangles(25, 50, 0);
    Grid g = buildGrid(scene);
    EXPECT_TRUE(walk(g, {100.0, 100.0, 100.0}, {1.0, 0.0, 0.0}).empty());
    EXPECT_TRUE(walk(g, {100.0, 0.0, 0.0}, {1.0, 0.0, 0.0}).empty()); // pointing away
}

} // namespace
} // namespace prism
