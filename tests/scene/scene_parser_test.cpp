// Every .scene directive on its good path (engine/scene/scene_parser.cpp,
// scene_directives.cpp): values, defaults, materials, paths.
#include <gtest/gtest.h>

#include "scene/scene_loader.h"
#include "temp_dir.h"

#include <cmath>

namespace prism {
namespace {

using test::TempDir;

Scene parse(std::string_view text) {
    return parseScene(text, "virtual/test.scene");
}

TEST(SceneParser, EmptySceneHasTheDocumentedDefaults) {
    Scene scene = parse("# nothing here\n\n   \t\n");
    EXPECT_EQ(scene.camera.eye, glm::dvec3(0, 0, 5));
    EXPECT_EQ(scene.camera.look, glm::dvec3(0, 0, 0));
    EXPECT_EQ(scene.camera.up, glm::vec3(0, 1, 0));
    EXPECT_EQ(scene.camera.fovDegrees, 60.0f);
    EXPECT_FALSE(scene.camera.isOrtho());
    EXPECT_EQ(scene.background, glm::vec3(0));
    EXPECT_EQ(scene.ambient, glm::vec3(1));
    EXPECT_TRUE(scene.lights.empty());
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material &m = scene.materials[0];
    EXPECT_EQ(m.name, "default");
    EXPECT_EQ(m.color, glm::vec3(0.8f));
    EXPECT_EQ(m.ambient, 0.1f);
    EXPECT_EQ(m.diffuse, 0.9f);
    EXPECT_EQ(m.specular, 0.0f);
    EXPECT_EQ(m.shininess, 32.0f);
    EXPECT_EQ(m.reflect, 0.0f);
    EXPECT_EQ(m.transmit, 0.0f);
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.texture, kNoTexture);
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(SceneParser, CameraTakesItsKeysInAnyOrder) {
    Scene scene = parse("camera fov 50 up 0 0 1 look 1 2 3 eye -1 -2 4.5\n");
    EXPECT_EQ(scene.camera.eye, glm::dvec3(-1, -2, 4.5));
    EXPECT_EQ(scene.camera.look, glm::dvec3(1, 2, 3));
    EXPECT_EQ(scene.camera.up, glm::vec3(0, 0, 1));
    EXPECT_EQ(scene.camera.fovDegrees, 50.0f);
    EXPECT_FALSE(scene.camera.isOrtho());
}

TEST(SceneParser, CameraOrthoMakesAParallelProjection) {
    Scene scene = parse("camera eye 0 0 10 look 0 0 0 ortho 4");
    EXPECT_TRUE(scene.camera.isOrtho());
    EXPECT_EQ(scene.camera.orthoHeight, 4.0f);
    EXPECT_EQ(scene.camera.fovDegrees, 60.0f);
}

TEST(SceneParser, BackgroundAndAmbient) {
    Scene scene = parse("background 0.05 0.05 0.1\nambient 0.2 0.3 2.5\n");
    EXPECT_EQ(scene.background, glm::vec3(0.05f, 0.05f, 0.1f));
    EXPECT_EQ(scene.ambient, glm::vec3(0.2f, 0.3f, 2.5f));
}

TEST(SceneParser, LightsWithAndWithoutOptions) {
    Scene scene = parse("light 5 8 -6\nlight 1 2 3 radius 0.5 color 0.5 0.25 2\n");
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].position, glm::dvec3(5, 8, -6));
    EXPECT_EQ(scene.lights[0].color, glm::vec3(1));
    EXPECT_EQ(scene.lights[0].radius, 0.0f);
    EXPECT_EQ(scene.lights[1].color, glm::vec3(0.5f, 0.25f, 2.0f));
    EXPECT_EQ(scene.lights[1].radius, 0.5f);
}

TEST(SceneParser, MaterialKeysAndDefaults) {
    Scene scene = parse("material glass color 1 0.5 0.25 ambient 0.2 diffuse 0 specular 1 "
                        "shininess 200 reflect 0.1 transmit 0.9 ior 1.33\n"
                        "material plain\n");
    ASSERT_EQ(scene.materials.size(), 3u);
    const Material &glass = scene.materials[1];
    EXPECT_EQ(glass.name, "glass");
    EXPECT_EQ(glass.color, glm::vec3(1, 0.5f, 0.25f));
    EXPECT_EQ(glass.ambient, 0.2f);
    EXPECT_EQ(glass.diffuse, 0.0f);
    EXPECT_EQ(glass.specular, 1.0f);
    EXPECT_EQ(glass.shininess, 200.0f);
    EXPECT_EQ(glass.reflect, 0.1f);
    EXPECT_EQ(glass.transmit, 0.9f);
    EXPECT_EQ(glass.ior, 1.33f);
    const Material &plain = scene.materials[2];
    EXPECT_EQ(plain.name, "plain");
    EXPECT_EQ(plain.color, glm::vec3(0.8f));
    EXPECT_EQ(plain.diffuse, 0.9f);
    EXPECT_EQ(plain.ior, 1.5f);
}

TEST(SceneParser, AMaterialMayBeNamedLikeAKey) {
    Scene scene = parse("material color color 1 0 0\nsphere 0 0 0 1 color\n");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[1].name, "color");
    EXPECT_EQ(scene.materials[1].color, glm::vec3(1, 0, 0));
    EXPECT_EQ(scene.spheres[0].material, 1u);
}

TEST(SceneParser, UseSetsTheMaterialOfPrimitivesThatNameNone) {
    Scene scene = parse("material red color 1 0 0\n"
                        "material blue color 0 0 1\n"
                        "sphere 0 0 0 1\n" // default
                        "use red\n"
                        "sphere 0 0 0 1\n" // red
                        "sphere 0 0 0 1 blue\n"
                        "plane 0 0 0 0 1 0\n" // red
                        "use default\n"
                        "triangle 0 0 0 1 0 0 0 1 0\n");
    ASSERT_EQ(scene.spheres.size(), 3u);
    EXPECT_EQ(scene.spheres[0].material, 0u);
    EXPECT_EQ(scene.spheres[1].material, 1u);
    EXPECT_EQ(scene.spheres[2].material, 2u);
    EXPECT_EQ(scene.planes[0].material, 1u);
    EXPECT_EQ(scene.triangles[0].material, 0u);
}

TEST(SceneParser, Sphere) {
    Scene scene = parse("sphere -1.5 1 0.25 2.5\n");
    ASSERT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.spheres[0].center, glm::dvec3(-1.5, 1, 0.25));
    EXPECT_EQ(scene.spheres[0].radius, 2.5f);
    EXPECT_EQ(scene.finitePrimitiveCount(), 1u);
}

TEST(SceneParser, PlaneNormalIsNormalised) {
    Scene scene = parse("plane 0 -1 0 0 0 3\nplane 1 2 3 3 0 4\n");
    ASSERT_EQ(scene.planes.size(), 2u);
    EXPECT_EQ(scene.planes[0].point, glm::dvec3(0, -1, 0));
    EXPECT_EQ(scene.planes[0].normal, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(scene.planes[1].normal.x, 0.6f);
    EXPECT_FLOAT_EQ(scene.planes[1].normal.z, 0.8f);
    EXPECT_EQ(scene.finitePrimitiveCount(), 0u); // planes live outside the grid
}

TEST(SceneParser, TriangleKeepsItsWinding) {
    Scene scene = parse("triangle 0 0 0  1 0 0  0 1 0\n");
    ASSERT_EQ(scene.triangles.size(), 1u);
    const Triangle &t = scene.triangles[0];
    EXPECT_EQ(t.p[0], glm::dvec3(0, 0, 0));
    EXPECT_EQ(t.p[1], glm::dvec3(1, 0, 0));
    EXPECT_EQ(t.p[2], glm::dvec3(0, 1, 0));
    EXPECT_EQ(t.shading, kNoShading);
}

TEST(SceneParser, ZeroAreaTrianglesAreDroppedWithAWarning) {
    Scene scene = parse("\ntriangle 0 0 0 1 1 1 2 2 2\n");
    EXPECT_TRUE(scene.triangles.empty());
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0],
              "virtual/test.scene:2: warning: 1 degenerate (zero-area) triangle dropped");
}

TEST(SceneParser, FacesFanTriangulateOverVertices) {
    Scene scene = parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\nf 1 2 3 4 5\n");
    ASSERT_EQ(scene.triangles.size(), 3u);
    const glm::dvec3 v[5] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 1.5, 0}};
    for (int k = 0; k < 3; ++k) { // (1, k+2, k+3)
        EXPECT_EQ(scene.triangles[k].p[0], v[0]);
        EXPECT_EQ(scene.triangles[k].p[1], v[k + 1]);
        EXPECT_EQ(scene.triangles[k].p[2], v[k + 2]);
    }
}

TEST(SceneParser, NegativeFaceIndicesCountBackFromTheLastVertex) {
    Scene scene = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -3 -1\n");
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].p[2], glm::dvec3(0, 1, 0));
    EXPECT_EQ(scene.triangles[1].p[0], glm::dvec3(0, 0, 0));
    EXPECT_EQ(scene.triangles[1].p[2], glm::dvec3(5, 5, 5));
}

TEST(SceneParser, FacesUseTheCurrentMaterial) {
    Scene scene = parse("material red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nuse red\nf 1 2 3\n");
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].material, 0u);
    EXPECT_EQ(scene.triangles[1].material, 1u);
}

TEST(SceneParser, CommentsTabsCrlfAndMissingFinalNewline) {
    Scene scene = parse("# header\r\n\tsphere\t0 0 0\t1   # trailing comment\r\n"
                        "light 1 1 1 # color 0 0 0\r\nsphere 0 0 0 2");
    ASSERT_EQ(scene.spheres.size(), 2u);
    EXPECT_EQ(scene.spheres[1].radius, 2.0f);
    EXPECT_EQ(scene.lights[0].color, glm::vec3(1)); // the comment was not read as a key
}

TEST(SceneParser, MeshVerticesDoNotShiftTheScenesOwnNumbering) {
    TempDir dir;
    dir.write("tri.obj", "v 7 7 7\nv 8 7 7\nv 7 8 7\nf 1 2 3\n");
    std::filesystem::path scene =
        dir.write("s.scene", "v 0 0 0\nv 1 0 0\nmesh tri.obj\nv 0 1 0\nf 1 2 -1\n");
    Scene loaded = loadScene(scene);
    ASSERT_EQ(loaded.triangles.size(), 2u);
    EXPECT_EQ(loaded.triangles[1].p[0], glm::dvec3(0, 0, 0));
    EXPECT_EQ(loaded.triangles[1].p[2], glm::dvec3(0, 1, 0));
}

TEST(SceneParser, RelativePathsResolveAgainstTheScenesDirectory) {
    TempDir dir;
    dir.write("scenes/models/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    dir.write("models/tri.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\nf 1 2 3\n");
    std::filesystem::path scene =
        dir.write("scenes/a.scene", "mesh models/tri.obj\nmesh ../models/tri.obj\n");
    Scene loaded = loadScene(scene);
    EXPECT_EQ(loaded.triangles.size(), 3u);
    EXPECT_EQ(loaded.triangles[0].p[1], glm::dvec3(1, 0, 0));
    EXPECT_EQ(loaded.triangles[2].p[1], glm::dvec3(2, 0, 0));
}

TEST(SceneParser, QuotedPathsMayContainSpaces) {
    TempDir dir;
    dir.write("my models/tri angle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::filesystem::path scene =
        dir.write("dir with spaces/s.scene",
                  "mesh \"../my models/tri angle.obj\"\t\"default\" # a quoted name works too\n");
    Scene loaded = loadScene(scene);
    ASSERT_EQ(loaded.triangles.size(), 1u);
    EXPECT_EQ(loaded.triangles[0].material, 0u);
}

TEST(SceneParser, MeshWithNameUsesThatMaterialForEveryFace) {
    TempDir dir;
    dir.write("m.mtl", "newmtl skin\nKd 1 0 0\n");
    dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl skin\nf 1 2 3\n"
                       "usemtl nowhere\nf 3 2 1\n");
    Scene loaded = loadScene(dir.write("s.scene", "material red\nmesh m.obj red\n"));
    ASSERT_EQ(loaded.triangles.size(), 2u);
    EXPECT_EQ(loaded.triangles[0].material, 1u);
    EXPECT_EQ(loaded.triangles[1].material, 1u);
    EXPECT_EQ(loaded.materials.size(), 2u); // the MTL was not read
    EXPECT_TRUE(loaded.warnings.empty());   // nor its usemtl lines checked
}

TEST(SceneParser, ExampleFromTheFormatLoads) {
    TempDir dir;
    dir.write("models/bunny.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Scene scene = loadScene(dir.write("example.scene", R"(# three spheres on a checker-free floor
camera eye 0 2 -8 look 0 1 0 fov 50
background 0.05 0.05 0.1
light 5 8 -6 color 1 1 1
material floor color 0.7 0.7 0.7 reflect 0.2
material glass color 1 1 1 diffuse 0 specular 1 shininess 200 transmit 0.9 ior 1.5
material red color 0.9 0.1 0.1 specular 0.5 shininess 64
plane 0 0 0 0 1 0 floor
sphere -1.5 1 0 1 glass
sphere 1.5 1 0 1 red
mesh models/bunny.obj red scale 8 translate 0 -0.3 2
)"));
    EXPECT_EQ(scene.materials.size(), 4u);
    EXPECT_EQ(scene.planes.size(), 1u);
    EXPECT_EQ(scene.spheres.size(), 2u);
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].p[1], glm::dvec3(8, -0.3, 2));
    EXPECT_EQ(scene.triangles[0].material, 3u);
    EXPECT_TRUE(scene.warnings.empty());
}

} // namespace
} // namespace prism
