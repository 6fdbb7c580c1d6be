// OBJ meshes in a scene (engine/scene/mesh_importer.cpp): placement, normals and UVs, MTL
// materials and their warnings, zero-area triangles.
#include <gtest/gtest.h>

#include "expect_file_error.h"
#include "scene/scene_loader.h"
#include "scene_warnings.h"
#include "temp_dir.h"

#include <OpenImageIO/imageio.h>

namespace prism {
namespace {

using test::allWarnings;
using test::expectFileError;
using test::TempDir;

const char *kTriangle = "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n";

void writePng(const std::filesystem::path &path, int width, int height, int channels,
              const std::vector<uint8_t> &pixels) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
}

bool hasWarning(const Scene &scene, const std::string &prefix, const std::string &fragment) {
    for (const std::string &w : scene.warnings)
        if (w.rfind(prefix, 0) == 0 && w.find(fragment) != std::string::npos)
            return true;
    return false;
}

TEST(MeshImporter, TransformsApplyScaleThenRotationsThenTranslationWhateverTheKeyOrder) {
    TempDir dir;
    dir.write("t.obj", kTriangle);
    Scene scene = loadScene(dir.write("s.scene", "mesh t.obj translate 1 0 0 rotate z 90 "
                                                 "scale 2 rotate x 90\n"));
    ASSERT_EQ(scene.triangles.size(), 1u);
    // (1,0,0): scale (2,0,0), z 90 (0,2,0), x 90 (0,0,2), translate (1,0,2).
    EXPECT_EQ(scene.triangles[0].p[0], glm::dvec3(1, 0, 2));
    // (0,1,0): scale (0,2,0), z 90 (-2,0,0), x 90 (-2,0,0), translate (-1,0,0).
    EXPECT_EQ(scene.triangles[0].p[1], glm::dvec3(-1, 0, 0));
    // (0,0,1): scale (0,0,2), z 90 (0,0,2), x 90 (0,-2,0), translate (1,-2,0).
    EXPECT_EQ(scene.triangles[0].p[2], glm::dvec3(1, -2, 0));
}

TEST(MeshImporter, VertexNormalsAreTransformedAndNormalised) {
    TempDir dir;
    dir.write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 3\nvn 0 2 2\nf 1//1 2//1 3//2\n");
    Scene scene =
        loadScene(dir.write("s.scene", "mesh n.obj scale 5 rotate x 90 translate 9 9 9\n"));
    ASSERT_EQ(scene.triangles.size(), 1u);
    const TriangleShading &t = scene.shadingOf(0);
    ASSERT_TRUE(t.hasNormals);
    EXPECT_EQ(t.n[0], glm::vec3(0, -1, 0)); // z -> -y under x 90
    EXPECT_FLOAT_EQ(t.n[2].y, -std::sqrt(0.5f));
    EXPECT_FLOAT_EQ(t.n[2].z, std::sqrt(0.5f));
    EXPECT_FLOAT_EQ(glm::length(t.n[2]), 1.0f);
}

TEST(MeshImporter, NormalsAndUvsOnlyWhenAllThreeCornersHaveThem) {
    TempDir dir;
    dir.write("q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
                       "vn 0 0 1\nvn 0 0 0\n"
                       "f 1/1/1 2/2/1 3/3/1 4//1\n" // fan: (1,2,3) full, (1,3,4) no UV at 4
                       "f 1/1/2 2/2/1 3/3/1\n");    // a zero normal: no vertex normals
    Scene scene = loadScene(dir.write("s.scene", "mesh q.obj\n"));
    ASSERT_EQ(scene.triangles.size(), 3u);
    EXPECT_TRUE(scene.shadingOf(0).hasUVs);
    EXPECT_TRUE(scene.shadingOf(0).hasNormals);
    EXPECT_EQ(scene.shadingOf(0).uv[2], glm::vec2(1, 1));
    EXPECT_EQ(scene.shadingOf(0).n[1], glm::vec3(0, 0, 1));
    EXPECT_FALSE(scene.shadingOf(1).hasUVs);
    EXPECT_TRUE(scene.shadingOf(1).hasNormals);
    EXPECT_EQ(scene.triangles[1].p[2], glm::dvec3(0, 1, 0));
    EXPECT_TRUE(scene.shadingOf(2).hasUVs);
    EXPECT_FALSE(scene.shadingOf(2).hasNormals);
}

// `f 1//1 2//2 3//3` after the vn lines were commented out: the mesh loads, its triangles use
// their geometric normals, and the scene says so once, at the OBJ line.
TEST(MeshImporter, FacesNamingMissingNormalsLoadWithAWarning) {
    TempDir dir;
    dir.write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n# vn 0 0 1\n"
                       "f 1//1 2//1 3//1\nf 2//1 4//1 3//1\n");
    Scene scene = loadScene(dir.write("s.scene", "mesh n.obj\n"));
    ASSERT_EQ(scene.triangles.size(), 2u);
    for (size_t i = 0; i < scene.triangles.size(); ++i)
        EXPECT_FALSE(scene.shadingOf(i).hasNormals);
    EXPECT_TRUE(scene.triangleShading.empty()) << "no record where a triangle has nothing in it";
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("n.obj:6: warning: face normal index 1 is out of range"),
              std::string::npos)
        << scene.warnings[0];
}

// A scene may name one OBJ any number of times; SceneLimits::maxTriangles stops it at the
// line that would go over, before the triangles are allocated (lowered here to reach it).
TEST(MeshImporter, TheTriangleLimitStopsTheLineThatWouldPassIt) {
    TempDir dir;
    dir.write("t.obj", kTriangle);
    SceneLimits limits;
    limits.maxTriangles = 3;
    std::string three = "mesh t.obj\nmesh t.obj translate 1 0 0\nmesh t.obj translate 2 0 0\n";
    EXPECT_EQ(loadScene(dir.write("ok.scene", three), limits).triangles.size(), 3u);
    expectFileError([&] { loadScene(dir.write("over.scene", three + "mesh t.obj\n"), limits); },
                    (dir.path() / "over.scene").string(), 4, "more than 3 triangles, the limit");
    // Triangles written in the scene itself count the same.
    expectFileError(
        [&] {
            parseScene("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\nf 1 2 3\nf 1 2 3\n",
                       dir.path() / "inline.scene", limits);
        },
        (dir.path() / "inline.scene").string(), 7, "more than 3 triangles");
}

TEST(MeshImporter, ZeroAreaTrianglesAreDroppedAndCountedInAWarning) {
    TempDir dir;
    dir.write("d.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 4\nf 1 2 4\n");
    Scene scene = loadScene(dir.write("s.scene", "sphere 0 0 0 1\nmesh d.obj\n"));
    EXPECT_EQ(scene.triangles.size(), 1u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], (dir.path() / "s.scene").string() +
                                     ":2: warning: 2 degenerate (zero-area) triangles in '" +
                                     (dir.path() / "d.obj").string() + "' dropped");
}

TEST(MeshImporter, MtlMaterialsAreAddedOnceWithObjQualifiedNames) {
    TempDir dir;
    dir.write("m.mtl", "newmtl red\nKd 1 0 0\nKs 0.2 0.4 0.6\nNs 10\nNi 1.2\nd 0.75\n"
                       "newmtl unused\nKd 0 0 1\n");
    dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl red\n"
                       "f 1 2 3\nusemtl unused\nusemtl red\nf 1 2 3\n");
    Scene scene = loadScene(dir.write("s.scene", "material cur color 0 1 0\nuse cur\n"
                                                 "mesh m.obj\nmesh m.obj translate 0 0 1\n"));
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    ASSERT_EQ(scene.materials.size(), 3u); // default, cur, m.obj:red (once, for both meshes)
    const Material &red = scene.materials[2];
    EXPECT_EQ(red.name, "m.obj:red");
    EXPECT_EQ(red.color, glm::vec3(1, 0, 0));
    EXPECT_FLOAT_EQ(red.specular, 0.4f);
    EXPECT_EQ(red.shininess, 10.0f);
    EXPECT_EQ(red.ior, 1.2f);
    EXPECT_EQ(red.transmit, 0.25f);
    EXPECT_EQ(red.ambient, 0.1f);
    EXPECT_EQ(red.diffuse, 0.9f);
    ASSERT_EQ(scene.triangles.size(), 6u);
    EXPECT_EQ(scene.triangles[0].material, 1u); // before any usemtl: the current material
    EXPECT_EQ(scene.triangles[1].material, 2u);
    EXPECT_EQ(scene.triangles[2].material, 2u);
    EXPECT_EQ(scene.triangles[4].material, 2u);
}

TEST(MeshImporter, MtlProblemsAreWarningsWithFallbacks) {
    TempDir dir;
    dir.write("m.mtl", "newmtl textured\nKd 0.5 0.5 0.5\nmap_Kd missing.png\n");
    dir.write("m.obj", "mtllib m.mtl\nmtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                       "usemtl ghost\nf 1 2 3\nusemtl textured\nf 1 2 3\n");
    std::string obj = (dir.path() / "m.obj").string();
    std::string mtl = (dir.path() / "m.mtl").string();
    Scene scene = loadScene(dir.write("s.scene", "material cur\nuse cur\nmesh m.obj\n"));
    ASSERT_EQ(scene.warnings.size(), 3u) << allWarnings(scene);
    EXPECT_TRUE(
        hasWarning(scene, obj + ":2: warning: cannot read material library '", "nowhere.mtl"))
        << allWarnings(scene);
    EXPECT_TRUE(hasWarning(scene, obj + ":6: warning: material 'ghost' is not defined",
                           "its faces use 'cur'"))
        << allWarnings(scene);
    EXPECT_TRUE(hasWarning(scene, mtl + ":3: warning: cannot read texture '",
                           "material 'textured' is used without it"))
        << allWarnings(scene);
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].material, 1u); // ghost -> current material
    const Material &textured = scene.materials[scene.triangles[1].material];
    EXPECT_EQ(textured.name, "m.obj:textured");
    EXPECT_EQ(textured.texture, kNoTexture);
    EXPECT_EQ(textured.color, glm::vec3(0.5f));
}

TEST(MeshImporter, MtlTexturesResolveAgainstTheMtlFileAndLoadOnce) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "mats/tex");
    writePng(dir.path() / "mats/tex/a b.png", 1, 1, 3, {255, 0, 0});
    std::filesystem::create_symlink("a b.png", dir.path() / "mats/tex/link.png");
    // Backslashes, a name with spaces, options before the file, and a second spelling (a
    // symlink) of the same image, which must be loaded once.
    dir.write("mats/m.mtl", "newmtl one\nmap_Kd tex\\a b.png\nnewmtl two\n"
                            "map_Kd -s 1 1 1 tex/../tex/link.png\n");
    dir.write("models/m.obj", "mtllib ..\\mats\\m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                              "usemtl one\nf 1 2 3\nusemtl two\nf 1 2 3\n");
    Scene scene = loadScene(dir.write("s.scene", "mesh models/m.obj\n"));
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    ASSERT_EQ(scene.textures.size(), 1u);
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.materials[1].texture, 0);
    EXPECT_EQ(scene.materials[2].texture, 0);
    EXPECT_EQ(scene.textures[0].width, 1);
    EXPECT_EQ(scene.textures[0].texels[0], glm::vec4(1, 0, 0, 1));
}

// Normal and bump maps are data: the same file as a colour texture is a second texture, not
// sRGB-decoded. An image that cannot be read is a warning at its MTL line, as for map_Kd.
TEST(MeshImporter, MtlBumpAndNormalMapsLoadAsDataWithWarningsAtTheirLine) {
    TempDir dir;
    writePng(dir.path() / "t.png", 1, 1, 3, {128, 128, 255});
    dir.write("m.mtl", "newmtl bumpy\nmap_Kd t.png\nbump -bm 0.25 t.png\nnorm missing.png\n"
                       "newmtl normal\nnorm t.png\n");
    dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                       "usemtl bumpy\nf 1 2 3\nusemtl normal\nf 1 2 3\n");
    std::string mtl = (dir.path() / "m.mtl").string();
    Scene scene = loadScene(dir.write("s.scene", "mesh m.obj\n"));
    ASSERT_EQ(scene.warnings.size(), 1u) << allWarnings(scene);
    EXPECT_TRUE(hasWarning(scene, mtl + ":4: warning: cannot read texture '",
                           "material 'bumpy' is used without it"))
        << allWarnings(scene);
    ASSERT_EQ(scene.textures.size(), 2u);
    const Material &bumpy = scene.materials[scene.triangles[0].material];
    const Material &normal = scene.materials[scene.triangles[1].material];
    EXPECT_EQ(bumpy.bumpScale, 0.25f);
    EXPECT_EQ(bumpy.normalMap, kNoTexture);
    EXPECT_NE(bumpy.bumpMap, bumpy.texture);
    EXPECT_EQ(normal.normalMap, bumpy.bumpMap); // one data copy of t.png
    glm::vec4 data = scene.textures[size_t(bumpy.bumpMap)].texels[0];
    EXPECT_EQ(data, glm::vec4(128 / 255.0f, 128 / 255.0f, 1.0f, 1.0f));
    glm::vec4 colour = scene.textures[size_t(bumpy.texture)].texels[0];
    EXPECT_NEAR(colour.x, 0.2158605f, 1e-6f); // sRGB 128 decoded
}

TEST(MeshImporter, MtllibMayNameSeveralFilesOrOneWithSpaces) {
    TempDir dir;
    dir.write("a.mtl", "newmtl a\nKd 1 0 0\n");
    dir.write("b.mtl", "newmtl b\nKd 0 1 0\n");
    dir.write("my mats.mtl", "newmtl c\nKd 0 0 1\n");
    dir.write("m.obj", "mtllib a.mtl b.mtl\nmtllib my mats.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                       "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\nusemtl c\nf 1 2 3\n");
    Scene scene = loadScene(dir.write("s.scene", "mesh m.obj\n"));
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    ASSERT_EQ(scene.triangles.size(), 3u);
    EXPECT_EQ(scene.materials[scene.triangles[0].material].color, glm::vec3(1, 0, 0));
    EXPECT_EQ(scene.materials[scene.triangles[1].material].color, glm::vec3(0, 1, 0));
    EXPECT_EQ(scene.materials[scene.triangles[2].material].color, glm::vec3(0, 0, 1));
}

TEST(MeshImporter, MtlMaterialsCannotBeNamedByUse) {
    TempDir dir;
    dir.write("m.mtl", "newmtl red\nKd 1 0 0\n");
    dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    std::filesystem::path scene = dir.write("s.scene", "mesh m.obj\nuse m.obj:red\n");
    test::expectFileError([&] { loadScene(scene); }, scene.string(), 2,
                          "unknown material 'm.obj:red'");
}

} // namespace
} // namespace prism
