// `mesh ... smooth [ANGLE]`: vertex normals from the geometry (engine/scene/vertex_normals.cpp),
// through the scene line and the OBJ's smoothing groups.
#include <cmath>

#include <gtest/gtest.h>

#include "core/parallel_for.h"
#include "expect_file_error.h"
#include "scene/obj_loader.h"
#include "scene/scene_loader.h"
#include "scene/vertex_normals.h"
#include "scene_warnings.h"
#include "temp_dir.h"

namespace prism {
namespace {

using test::expectFileError;
using test::TempDir;

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// Two faces of a cube at the edge x = 1, z = 1: the top (+y) and the side (+x), meeting at 90.
// The top is one triangle, the side fanned into three meeting at the shared corner (1, 1, 1):
// by angle the side still weighs 90 degrees at that corner, as the top does (by count it would
// weigh three times as much, by area otherwise).
// (1, 1, 0) is two vertices, one the top's and one the side's: only the corner c is shared.
const std::vector<glm::dvec3> kTopAndSide = {{1, 1, 1}, {1, 1, 0}, {0, 1, 1}, // c, then the top
                                             {1, 1, 0}, {1, 0, 0}, {1, 0, 0.5}, {1, 0, 1}};

std::vector<SmoothingTriangle> topAndFannedSide() {
    std::vector<SmoothingTriangle> t;
    t.push_back({{0, 1, 2}, 0});     // +y, 90 degrees at c
    for (uint32_t k = 0; k < 3; ++k) // +x: counter-clockwise seen from +x
        t.push_back({{0, 4 + k, 3 + k}, 0});
    return t;
}

glm::dvec3 corner(const SmoothingTriangle &t, int c) {
    return kTopAndSide[t.vertex[size_t(c)]];
}

TEST(VertexNormals, AngleWeightedIgnoresHowAFaceWasCut) {
    std::vector<SmoothingTriangle> t = topAndFannedSide();
    for (int k = 1; k < 4; ++k) // every side triangle faces +x (counter-clockwise seen from +x)
        expectNear(glm::vec3(glm::normalize(glm::cross(corner(t[k], 1) - corner(t[k], 0),
                                                       corner(t[k], 2) - corner(t[k], 0)))),
                   glm::vec3(1, 0, 0));
    auto n = smoothVertexNormals(kTopAndSide, t, 180.0); // no crease: one surface
    glm::vec3 diagonal = glm::normalize(glm::vec3(1, 1, 0));
    for (int k = 0; k < 4; ++k)
        expectNear(n[size_t(k)][0], diagonal); // the shared corner: 90 degrees of each face
}

TEST(VertexNormals, CreasesAndSmoothingGroupsSplit) {
    std::vector<SmoothingTriangle> t = topAndFannedSide();
    auto creased =
        smoothVertexNormals(kTopAndSide, t, 60.0); // 90 degrees is a crease: facets stay flat
    expectNear(creased[0][0], glm::vec3(0, 1, 0));
    expectNear(creased[2][0], glm::vec3(1, 0, 0));
    t[0].group = 7; // another smoothing group: split even without a crease
    auto grouped = smoothVertexNormals(kTopAndSide, t, 180.0);
    expectNear(grouped[0][0], glm::vec3(0, 1, 0));
    expectNear(grouped[1][0], glm::vec3(1, 0, 0));
}

TEST(VertexNormals, SmoothMeshLineGivesUnitNormalsAndKeepsTheFilesOwn) {
    TempDir dir;
    // A pyramid without normals (faces meet at ~110 degrees) and one triangle with its own.
    dir.write("p.obj", "v 0 1 0\nv -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\nvn 0 0 1\n"
                       "f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 2\nf 2//1 5//1 4//1\n");
    Scene flat = loadScene(dir.write("a.scene", "mesh p.obj\n"));
    Scene soft = loadScene(dir.write("b.scene", "mesh p.obj smooth 120 translate 0 1 0\n"));
    Scene sharp = loadScene(dir.write("c.scene", "mesh p.obj smooth\n"));
    ASSERT_EQ(soft.triangles.size(), 5u);
    EXPECT_FALSE(flat.shadingOf(0).hasNormals);
    EXPECT_TRUE(soft.shadingOf(0).hasNormals);
    expectNear(soft.shadingOf(0).n[0], glm::vec3(0, 1, 0)); // the apex, by symmetry
    EXPECT_EQ(soft.shadingOf(4).n[0], glm::vec3(0, 0, 1));  // the file's own normal stays
    EXPECT_EQ(soft.triangles[0].p[0], glm::dvec3(0, 2, 0)); // keys in any order
    for (size_t i = 0; i < sharp.triangles.size(); ++i)     // 60 degrees: every edge is a crease
        for (const glm::vec3 &n : sharp.shadingOf(i).n)
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    glm::dvec3 e1 = sharp.triangles[0].p[1] - sharp.triangles[0].p[0];
    glm::dvec3 e2 = sharp.triangles[0].p[2] - sharp.triangles[0].p[0];
    expectNear(sharp.shadingOf(0).n[0], glm::vec3(glm::normalize(glm::cross(e1, e2))));
}

// A file that repeats each vertex for every face it is in (as STL exports are) smooths as the
// same mesh with shared vertices: its corners are welded by position, -0 and +0 as one.
TEST(VertexNormals, RepeatedVerticesAreWeldedByPosition) {
    TempDir dir;
    dir.write("shared.obj", "v 0 1 0\nv -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
                            "f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 2\n");
    dir.write("repeated.obj", "v 0 1 0\nv -1 0 1\nv 1 0 1\n"
                              "v -0 1 0\nv 1 0 1\nv 1 0 -1\n"
                              "v 0 1 -0\nv 1 0 -1\nv -1 0 -1\n"
                              "v 0 1 0\nv -1 0 -1\nv -1 0 1\n"
                              "f 1 2 3\nf 4 5 6\nf 7 8 9\nf 10 11 12\n");
    Scene shared = loadScene(dir.write("a.scene", "mesh shared.obj smooth 120\n"));
    Scene repeated = loadScene(dir.write("b.scene", "mesh repeated.obj smooth 120\n"));
    ASSERT_EQ(repeated.triangles.size(), 4u);
    expectNear(repeated.shadingOf(0).n[0], glm::vec3(0, 1, 0)); // the apex, by symmetry
    for (size_t i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(repeated.shadingOf(i).n[c], shared.shadingOf(i).n[c]) << i << " " << c;
}

// The passes over triangles run on every core; each triangle's normals are its own sums in
// one order, so the thread count changes nothing, to the bit.
TEST(VertexNormals, TheSameNormalsOnAnyNumberOfThreads) {
    constexpr uint32_t kSide = 120; // 28,800 triangles: several chunks of the parallel passes
    std::vector<glm::dvec3> positions;
    for (uint32_t z = 0; z <= kSide; ++z)
        for (uint32_t x = 0; x <= kSide; ++x)
            positions.push_back({x, std::sin(0.3 * x) * std::cos(0.2 * z), z});
    std::vector<SmoothingTriangle> triangles;
    for (uint32_t z = 0; z < kSide; ++z)
        for (uint32_t x = 0; x < kSide; ++x) {
            uint32_t v = z * (kSide + 1) + x, below = v + kSide + 1;
            triangles.push_back({{v, below, v + 1}, (x / 30) % 2}); // bands of two groups
            triangles.push_back({{v + 1, below, below + 1}, (x / 30) % 2});
        }
    auto normalsOn = [&](unsigned threads) {
        ParallelThreads limit(threads);
        return smoothVertexNormals(positions, triangles, 40.0);
    };
    auto one = normalsOn(1);
    ASSERT_EQ(one.size(), triangles.size());
    EXPECT_TRUE(one == normalsOn(2));
    EXPECT_TRUE(one == normalsOn(5));
}

TEST(VertexNormals, BadCreaseAnglesAreErrorsOfTheMeshLine) {
    TempDir dir;
    dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for (const char *bad : {"-1", "181", "x"})
        expectFileError(
            [&] {
                loadScene(dir.write("s.scene", "\nmesh t.obj smooth " + std::string(bad) + "\n"));
            },
            (dir.path() / "s.scene").string(), 2, bad[0] == 'x' ? "bad number" : "crease angle");
}

TEST(VertexNormals, ObjSmoothingGroupsAreRead) {
    ObjModel m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ns 2\nf 1 2 3\ns off\nf 1 2 3\n"
                          "s 1\nf 1 2 3\ns 0\nf 1 2 3\ns maybe\nf 1 2 3\n",
                          "g.obj");
    ASSERT_EQ(m.faces.size(), 6u);
    EXPECT_EQ(m.faces[0].smoothingGroup, 0u);
    EXPECT_EQ(m.faces[1].smoothingGroup, 2u);
    EXPECT_EQ(m.faces[2].smoothingGroup, 0u);
    EXPECT_EQ(m.faces[3].smoothingGroup, 1u);
    EXPECT_EQ(m.faces[4].smoothingGroup, 0u);
    EXPECT_EQ(m.faces[5].smoothingGroup, 0u);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("g.obj:13: warning: smoothing group"), std::string::npos)
        << m.warnings[0];
}

} // namespace
} // namespace prism
