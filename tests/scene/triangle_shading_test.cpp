// Triangles and their shading records (scene/scene.h): a triangle points into its owner's list,
// and whoever moves triangles from one owner to another carries the records with them.
#include <gtest/gtest.h>

#include "scene/instance_flattening.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace prism {
namespace {

using test::TempDir;

Triangle triangleAt(double x) {
    Triangle t;
    t.p[0] = {x, 0, 0};
    t.p[1] = {x + 1, 0, 0};
    t.p[2] = {x, 1, 0};
    return t;
}

TriangleShading normalsAlong(glm::vec3 n) {
    TriangleShading s;
    s.hasNormals = true;
    s.n[0] = s.n[1] = s.n[2] = n;
    return s;
}

TEST(TriangleShading, AppendedTrianglesPointToTheirOwnRecordsInTheNewList) {
    std::vector<Triangle> to = {triangleAt(0)};
    std::vector<TriangleShading> toShading;
    shadingFor(to[0], toShading) = normalsAlong({1, 0, 0});

    // The source's second triangle has no record; its first and third point to records in the
    // reverse of their order.
    std::vector<Triangle> from = {triangleAt(1), triangleAt(2), triangleAt(3)};
    std::vector<TriangleShading> fromShading = {normalsAlong({0, 0, 1}), normalsAlong({0, 1, 0})};
    from[0].shading = 1;
    from[2].shading = 0;
    appendTriangles(to, toShading, from, fromShading);

    ASSERT_EQ(to.size(), 4u);
    ASSERT_EQ(toShading.size(), 3u);
    EXPECT_EQ(to[0].shading, 0u); // the list's own triangle is left alone
    EXPECT_EQ(to[1].p[0], glm::dvec3(1, 0, 0));
    EXPECT_EQ(shadingOf(to[1], toShading).n[0], glm::vec3(0, 1, 0));
    EXPECT_EQ(to[2].shading, kNoShading);
    EXPECT_FALSE(shadingOf(to[2], toShading).hasNormals);
    EXPECT_EQ(shadingOf(to[3], toShading).n[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(shadingOf(to[0], toShading).n[0], glm::vec3(1, 0, 0));
}

// Two meshes with normals in one scene: the second is appended to the first's triangles, and
// its triangles keep their own normals (not the first mesh's records at the same indices).
TEST(TriangleShading, ASecondMeshKeepsItsOwnNormals) {
    TempDir dir;
    dir.write("up.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1 0\nf 1//1 2//1 3//1\n");
    dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    dir.write("side.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nf 1//1 2//1 3//1\n");
    Scene scene = loadScene(dir.write("s.scene", "mesh up.obj\nmesh flat.obj translate 2 0 0\n"
                                                 "mesh side.obj translate 4 0 0\n"));
    ASSERT_EQ(scene.triangles.size(), 3u);
    EXPECT_EQ(scene.triangleShading.size(), 2u) << "no record for the flat mesh's triangle";
    EXPECT_EQ(scene.shadingOf(0).n[0], glm::vec3(0, 1, 0));
    EXPECT_FALSE(scene.shadingOf(1).hasNormals);
    EXPECT_TRUE(scene.shadingOf(2).hasNormals);
    EXPECT_EQ(scene.shadingOf(2).n[0], glm::vec3(1, 0, 0));
}

// Instances written out: each placement's triangles get records of their own, turned with it.
TEST(TriangleShading, FlattenedInstancesCarryTheirTurnedNormals) {
    TempDir dir;
    dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
    Scene scene = loadScene(dir.write("s.scene", "mesh m.obj as m\nplace m\n"
                                                 "place m rotate y 90 translate 3 0 0\n"));
    Scene flat = flattenInstances(scene);
    ASSERT_EQ(flat.triangles.size(), 2u);
    ASSERT_EQ(flat.triangleShading.size(), 2u);
    EXPECT_NE(flat.triangles[0].shading, flat.triangles[1].shading);
    EXPECT_EQ(flat.shadingOf(0).n[0], glm::vec3(0, 0, 1));
    glm::vec3 turned = flat.shadingOf(1).n[0]; // +z turned 90 degrees about +y: +x
    EXPECT_NEAR(turned.x, 1.0f, 1e-6f);
    EXPECT_NEAR(turned.z, 0.0f, 1e-6f);
    EXPECT_EQ(scene.prototypes[0].shading[0].n[0], glm::vec3(0, 0, 1)) << "the prototype unturned";
}

} // namespace
} // namespace prism
