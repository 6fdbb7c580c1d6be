// Instanced meshes (format 1.1, docs/scene-format.md "Instances"): `mesh ... as ID` makes a
// centred prototype that draws nothing, `place ID ...` adds instances of it
// (engine/scene/scene_directives.cpp).
#include <gtest/gtest.h>

#include "expect_file_error.h"
#include "scene/mesh_transform.h"
#include "scene/scene_loader.h"
#include "scene_warnings.h"
#include "temp_dir.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

using test::allWarnings;
using test::expectFileError;
using test::TempDir;

// A tetrahedron off the origin: bounding box (1,2,3)-(4,6,8), centre (2.5, 4, 5.5).
const char *kTetra = "v 1 2 3\nv 4 2 3\nv 1 6 3\nv 1 2 8\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const glm::dvec3 kTetraCentre(2.5, 4, 5.5);

void expectNearRelative(const glm::dvec3 &actual, const glm::dvec3 &expected) {
    double tolerance = 1e-9 * std::max(1.0, glm::length(expected));
    EXPECT_LE(glm::length(actual - expected), tolerance)
        << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", "
        << expected.y << ", " << expected.z << ")";
}

// Every vertex of `instance` in world space equals the matching one of `plain` (the triangles
// of a `mesh` line with the same transform) within 1e-9 relative.
void expectPlacedLike(const Scene &scene, const Instance &instance,
                      const std::vector<Triangle> &plain) {
    const MeshPrototype &prototype = scene.prototypes.at(instance.prototype);
    ASSERT_EQ(prototype.triangles.size(), plain.size());
    for (size_t i = 0; i < plain.size(); ++i)
        for (int c = 0; c < 3; ++c)
            expectNearRelative(instance.toWorld(prototype.triangles[i].p[c]), plain[i].p[c]);
}

TEST(Instances, AsMakesACentredPrototypeThatDrawsNothing) {
    TempDir dir;
    dir.write("m.obj", kTetra);
    Scene scene = loadScene(dir.write("s.scene", "mesh m.obj as thing\n"));
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    EXPECT_TRUE(scene.triangles.empty());
    EXPECT_TRUE(scene.instances.empty());
    ASSERT_EQ(scene.prototypes.size(), 1u);
    const MeshPrototype &prototype = scene.prototypes[0];
    EXPECT_EQ(prototype.name, "thing");
    ASSERT_EQ(prototype.triangles.size(), 4u);
    EXPECT_EQ(prototype.triangles[0].p[0], glm::dvec3(1, 2, 3) - kTetraCentre);
    EXPECT_EQ(prototype.triangles[0].p[1], glm::dvec3(1, 6, 3) - kTetraCentre);
    EXPECT_EQ(prototype.triangles[0].p[2], glm::dvec3(4, 2, 3) - kTetraCentre);
    EXPECT_EQ(scene.finitePrimitiveCount(), 0u);
}

TEST(Instances, PlaceStoresScaleRotationAndATranslationThatTakesTheCentreIn) {
    TempDir dir;
    dir.write("m.obj", kTetra);
    Scene scene =
        loadScene(dir.write("s.scene", "mesh m.obj as thing\n"
                                       "place thing\n"
                                       "place thing scale 2 rotate y 90 translate 10 0 0\n"
                                       "place thing translate 1 2 3 rotate x 30 scale 0.5 "
                                       "rotate z -45\n"));
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    EXPECT_TRUE(scene.triangles.empty());
    ASSERT_EQ(scene.prototypes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 3u);
    EXPECT_EQ(scene.finitePrimitiveCount(), 3u);

    const Instance &plain = scene.instances[0];
    EXPECT_EQ(plain.prototype, 0u);
    EXPECT_EQ(plain.scale, 1.0);
    EXPECT_EQ(plain.rotation, glm::dmat3(1.0));
    EXPECT_EQ(plain.translation, kTetraCentre); // the prototype back where the OBJ has it
    EXPECT_EQ(plain.material, kOwnMaterials);

    const Instance &turned = scene.instances[1];
    EXPECT_EQ(turned.scale, 2.0);
    // rotate y 90 takes +z to +x and +x to -z (glm: columns are the images of x, y, z).
    EXPECT_EQ(turned.rotation,
              glm::dmat3(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0)));
    // 10 0 0 + 2 * R * (2.5, 4, 5.5) = 10 0 0 + 2 * (5.5, 4, -2.5)
    EXPECT_EQ(turned.translation, glm::dvec3(21, 8, -5));

    const Instance &third = scene.instances[2];
    EXPECT_EQ(third.scale, 0.5);
    glm::dmat3 rotation = axisRotation(2, -45) * axisRotation(0, 30); // in the order written
    for (int column = 0; column < 3; ++column)
        expectNearRelative(third.rotation[column], rotation[column]);
    expectNearRelative(third.translation, glm::dvec3(1, 2, 3) + 0.5 * (rotation * kTetraCentre));
}

TEST(Instances, APlacementPutsVerticesWhereAMeshLineWithItsKeysWould) {
    TempDir dir;
    dir.write("m.obj", kTetra);
    const std::vector<std::string> transforms = {
        "",
        "scale 2 rotate y 90 translate 10 0 0",
        "rotate x 30 rotate z -45 scale 0.5 translate 1 2 3",
        "rotate z 17.5 rotate y 123 rotate x -3 scale 1000 translate 1000000.3 -20 5e5",
    };
    std::string places = "mesh m.obj as thing\n";
    for (const std::string &transform : transforms)
        places += "place thing " + transform + "\n";
    Scene scene = loadScene(dir.write("s.scene", places));
    ASSERT_EQ(scene.instances.size(), transforms.size());
    for (size_t i = 0; i < transforms.size(); ++i) {
        SCOPED_TRACE(transforms[i]);
        Scene mesh = loadScene(dir.write("plain.scene", "mesh m.obj " + transforms[i] + "\n"));
        expectPlacedLike(scene, scene.instances[i], mesh.triangles);
    }
}

// The `mesh ... as` line's own keys shape the prototype (placement, smoothing); `place`
// then moves the result.
TEST(Instances, TheMeshLinesOwnTransformAndSmoothingGoIntoThePrototype) {
    TempDir dir;
    dir.write("m.obj", kTetra);
    const std::string meshKeys = "scale 3 rotate x 90 translate 5 5 5 smooth 180";
    Scene scene = loadScene(dir.write("s.scene", "mesh m.obj " + meshKeys +
                                                     " as t\nplace t rotate y 30 translate "
                                                     "1 1 1\n"));
    Scene mesh = loadScene(dir.write("plain.scene", "mesh m.obj " + meshKeys + "\n"));
    ASSERT_EQ(scene.instances.size(), 1u);
    const MeshPrototype &prototype = scene.prototypes[0];
    ASSERT_EQ(prototype.triangles.size(), mesh.triangles.size());
    glm::dmat3 rotation = axisRotation(1, 30);
    std::vector<Triangle> expected = mesh.triangles;
    for (Triangle &t : expected)
        for (glm::dvec3 &p : t.p)
            p = glm::dvec3(1, 1, 1) + rotation * p;
    expectPlacedLike(scene, scene.instances[0], expected);
    for (size_t i = 0; i < prototype.triangles.size(); ++i) {
        EXPECT_TRUE(prototype.shadingOf(i).hasNormals);
        for (int c = 0; c < 3; ++c) // normals are not moved by the centring
            EXPECT_EQ(prototype.shadingOf(i).n[c], mesh.shadingOf(i).n[c]);
    }
}

TEST(Instances, PlaceWithANameOverridesEveryFacesMaterial) {
    TempDir dir;
    dir.write("m.obj", kTetra);
    Scene scene = loadScene(dir.write("s.scene", "material red color 1 0 0\n"
                                                 "material blue color 0 0 1\n"
                                                 "use blue\n"
                                                 "mesh m.obj as t\n"
                                                 "mesh m.obj red as named\n"
                                                 "place t red\n"
                                                 "place t default scale 2\n"
                                                 "place t\n"
                                                 "place named\n"));
    ASSERT_EQ(scene.prototypes.size(), 2u);
    for (const Triangle &t : scene.prototypes[0].triangles)
        EXPECT_EQ(t.material, 2u); // the current material at the `mesh` line
    for (const Triangle &t : scene.prototypes[1].triangles)
        EXPECT_EQ(t.material, 1u); // the mesh line's NAME
    ASSERT_EQ(scene.instances.size(), 4u);
    EXPECT_EQ(scene.instances[0].material, 1);
    EXPECT_EQ(scene.instances[1].material, 0);
    EXPECT_EQ(scene.instances[2].material, kOwnMaterials);
    EXPECT_EQ(scene.instances[3].material, kOwnMaterials);
    EXPECT_EQ(scene.instances[3].prototype, 1u);
}

TEST(Instances, APrototypeKeepsItsMtlMaterials) {
    TempDir dir;
    dir.write("m.mtl", "newmtl red\nKd 1 0 0\n");
    dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl red\nf 1 3 2\n");
    Scene scene = loadScene(dir.write("s.scene", "mesh m.obj as t\nplace t\n"));
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[1].name, "m.obj:red");
    EXPECT_EQ(scene.materials[1].color, glm::vec3(1, 0, 0));
    ASSERT_EQ(scene.prototypes.at(0).triangles.size(), 2u);
    EXPECT_EQ(scene.prototypes[0].triangles[0].material, 0u);
    EXPECT_EQ(scene.prototypes[0].triangles[1].material, 1u);
    EXPECT_EQ(scene.instances.at(0).material, kOwnMaterials);
}

// Loading `text`, written to `name` in `dir`, under `limits` fails at its line `line`.
void expectOverLimit(const TempDir &dir, const std::string &name, const std::string &text,
                     const SceneLimits &limits, int line, const std::string &fragment) {
    expectFileError([&] { loadScene(dir.write(name, text), limits); }, (dir.path() / name).string(),
                    line, fragment);
}

// A prototype's triangles take memory once: they count against SceneLimits::maxTriangles at
// the `mesh ... as` line, and its placements do not.
TEST(Instances, PrototypeTrianglesCountAgainstTheTriangleLimitOnce) {
    TempDir dir;
    dir.write("m.obj", kTetra);
    SceneLimits limits;
    limits.maxTriangles = 9;
    std::string nine = "mesh m.obj as a\nmesh m.obj as b\nplace a\nplace a\nplace b\n"
                       "triangle 0 0 0 1 0 0 0 1 0\n";
    Scene scene = loadScene(dir.write("ok.scene", nine), limits);
    EXPECT_EQ(scene.triangles.size() + scene.prototypes[0].triangles.size() +
                  scene.prototypes[1].triangles.size(),
              9u);
    const std::string over = "more than 9 triangles, the limit (SceneLimits::maxTriangles)";
    expectOverLimit(dir, "tri.scene", nine + "triangle 0 0 0 1 0 0 0 1 0\n", limits, 7, over);
    expectOverLimit(dir, "proto.scene", nine + "mesh m.obj as c\n", limits, 7, over);
    expectOverLimit(dir, "mesh.scene", nine + "mesh m.obj\n", limits, 7, over);
}

TEST(Instances, TheInstanceLimitStopsThePlaceLineThatWouldPassIt) {
    TempDir dir;
    dir.write("m.obj", kTetra);
    SceneLimits limits;
    limits.maxInstances = 2;
    std::string two = "mesh m.obj as a\nplace a\nplace a translate 1 0 0\n";
    EXPECT_EQ(loadScene(dir.write("ok.scene", two), limits).instances.size(), 2u);
    expectOverLimit(dir, "over.scene", two + "place a\n", limits, 4,
                    "the scene would hold more than 2 instances, the limit "
                    "(SceneLimits::maxInstances)");
    EXPECT_EQ(SceneLimits().maxInstances, uint64_t(1) << 22);
}

TEST(Instances, PlacingAPrototypeWithoutTrianglesWarnsOncePerLine) {
    TempDir dir;
    dir.write("d.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    dir.write("m.obj", kTetra);
    std::string file = (dir.path() / "s.scene").string();
    Scene scene = loadScene(dir.write("s.scene", "mesh d.obj as empty\nmesh m.obj as full\n"
                                                 "place empty\nplace full\n"
                                                 "place empty translate 1 0 0\n"));
    EXPECT_EQ(scene.prototypes.size(), 1u); // an empty prototype is not handed on
    EXPECT_EQ(scene.prototypes[0].name, "full");
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_EQ(scene.instances[0].prototype, 0u);
    ASSERT_EQ(scene.warnings.size(), 3u) << allWarnings(scene);
    EXPECT_EQ(scene.warnings[0], file + ":1: warning: 1 degenerate (zero-area) triangle in '" +
                                     (dir.path() / "d.obj").string() + "' dropped");
    EXPECT_EQ(scene.warnings[1],
              file + ":3: warning: prototype 'empty' (line 1) has no triangles; nothing is placed");
    EXPECT_EQ(scene.warnings[2],
              file + ":5: warning: prototype 'empty' (line 1) has no triangles; nothing is placed");
}

TEST(Instances, InstanceErrorsNameTheirLine) {
    TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::string scene = (dir.path() / "s.scene").string();
    auto expectError = [&](const std::string &lines, int line, const std::string &fragment) {
        SCOPED_TRACE(lines);
        dir.write("s.scene", "# instances\nmesh tri.obj as a\n" + lines);
        expectFileError([&] { loadScene(scene); }, scene, line, fragment);
    };
    expectError("sphere 0 0 0 1\nmesh tri.obj as a\n", 4,
                "prototype 'a' is already defined at line 2");
    expectError("place b\n", 3, "unknown prototype 'b'");
    expectError("place a nosuch\n", 3, "unknown material 'nosuch'");
    expectError("place a scale 0\n", 3, "'scale' must be > 0, got 0");
    expectError("place a scale -2\n", 3, "'scale' must be > 0, got -2");
    expectError("place a rotate w 90\n", 3, "rotate axis must be x, y or z, got 'w'");
    expectError("place a rotate y\n", 3, "'rotate' needs 2 values");
    expectError("place a translate 1 2\n", 3, "'translate' needs 3 values");
    expectError("place a scale 2 scale 3\n", 3, "'scale' is given twice");
    expectError("place a default smooth\n", 3, "unknown key 'smooth' for 'place'");
    expectError("place a default 1\n", 3, "extra argument '1'");
    expectError("place\n", 3,
                "missing argument (usage: place ID [NAME] [scale S] [rotate AXIS DEG]... "
                "[translate X Y Z])");
    expectError("mesh tri.obj as\n", 3, "'as' needs 1 value");
    expectError("mesh tri.obj as b as c\n", 3, "'as' is given twice");
    // The box (0,0,0)-(1,1,0), centred, reaches half a unit each way in x and y: at scale 1e38
    // and 3e38 along an axis a corner passes FLT_MAX (3.4e38).
    // The tracer's inverse map, 1 / scale and translation / scale, must fit a float as well.
    expectError("place a scale 1e-39\n", 3,
                "'scale' 1e-39 is too small for the placement to be undone in 32-bit floats");
    expectError("place a scale 1e-10 translate 1e30 0 0\n", 3,
                "'scale' 1e-10 is too small for the placement to be undone in 32-bit floats");
    expectError("place a scale 1e38 translate 3e38 0 0\n", 3,
                "the placement takes the bounding box of prototype 'a' out of the range of a "
                "32-bit float");
    expectError("place a scale 1e38 rotate z -90 translate 0 -3e38 0\n", 3, "32-bit float");
    dir.write("s.scene", "place a\nmesh tri.obj as a\n"); // a prototype is defined above its use
    expectFileError([&] { loadScene(scene); }, scene, 1, "unknown prototype 'a'");
}

} // namespace
} // namespace prism
