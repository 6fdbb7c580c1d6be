// `mesh ... smooth [ANGLE]`: vertex normals from the geometry (engine/scene/vertex_normals.cpp),
// through the scene line and the OBJ's smoothing groups.
#include <cmath>

#include <gtest/gtest.h>

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
std::vector<SmoothingTriangle> topAndFannedSide() {
    glm::dvec3 c(1, 1, 1);
    std::vector<SmoothingTriangle> t;
    t.push_back({{c, glm::dvec3(1, 1, 0), glm::dvec3(0, 1, 1)}, {0, 1, 2}, 0}); // +y, 90 at c
    glm::dvec3 fan[4] = {{1, 1, 0}, {1, 0, 0}, {1, 0, 0.5}, {1, 0, 1}};
    for (int k = 0; k < 3; ++k) // +x: counter-clockwise seen from +x
        t.push_back({{c, fan[k + 1], fan[k]}, {0, uint32_t(4 + k), uint32_t(3 + k)}, 0});
    return t;
}

TEST(VertexNormals, AngleWeightedIgnoresHowAFaceWasCut) {
    std::vector<SmoothingTriangle> t = topAndFannedSide();
    for (int k = 1; k < 4; ++k) // every side triangle faces +x (counter-clockwise seen from +x)
        expectNear(
            glm::vec3(glm::normalize(glm::cross(t[k].p[1] - t[k].p[0], t[k].p[2] - t[k].p[0]))),
            glm::vec3(1, 0, 0));
    auto n = smoothVertexNormals(t, 180.0); // no crease: one surface
    glm::vec3 diagonal = glm::normalize(glm::vec3(1, 1, 0));
    for (int k = 0; k < 4; ++k)
        expectNear(n[size_t(k)][0], diagonal); // the shared corner: 90 degrees of each face
}

TEST(VertexNormals, CreasesAndSmoothingGroupsSplit) {
    std::vector<SmoothingTriangle> t = topAndFannedSide();
    auto creased = smoothVertexNormals(t, 60.0); // 90 degrees is a crease: facets stay flat
    expectNear(creased[0][0], glm::vec3(0, 1, 0));
    expectNear(creased[2][0], glm::vec3(1, 0, 0));
    t[0].group = 7; // another smoothing group: split even without a crease
    auto grouped = smoothVertexNormals(t, 180.0);
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
