// The shipped models (assets/models, see SOURCES.md) load with the counts, materials and
// textures they are known to have.
#include <gtest/gtest.h>

#include "core/timer.h"
#include "scene/scene_loader.h"
#include "scene_warnings.h"
#include "temp_dir.h"

#include <set>
#include <sstream>

namespace prism {
namespace {

using test::allWarnings;

// Parses `text` as if it were a scene file in assets/models/.
Scene modelsScene(const std::string &text) {
    return parseScene(text, std::filesystem::path(PRISM_ASSETS_DIR) / "models" / "test.scene");
}

TEST(ModelAssets, CornellBoxCrlfNegativeIndicesAndMaterials) {
    Scene scene = modelsScene("mesh cornell-box/CornellBox-Original.obj\n");
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    ASSERT_EQ(scene.triangles.size(), 36u); // 18 quads
    ASSERT_EQ(scene.materials.size(), 9u);  // default + 8
    std::set<std::string> names;
    for (size_t i = 1; i < scene.materials.size(); ++i)
        names.insert(scene.materials[i].name);
    const std::string prefix = "cornell-box/CornellBox-Original.obj:";
    EXPECT_EQ(names,
              (std::set<std::string>{prefix + "floor", prefix + "ceiling", prefix + "backWall",
                                     prefix + "rightWall", prefix + "leftWall", prefix + "shortBox",
                                     prefix + "tallBox", prefix + "light"}));
    // The floor quad "f -4 -3 -2 -1" over its 4 vertices, fanned.
    const Triangle &floor = scene.triangles[0];
    EXPECT_EQ(floor.p[0], glm::dvec3(glm::vec3(-1.01f, 0.0f, 0.99f)));
    EXPECT_EQ(floor.p[1], glm::dvec3(glm::vec3(1.0f, 0.0f, 0.99f)));
    EXPECT_EQ(floor.p[2], glm::dvec3(glm::vec3(1.0f, 0.0f, -1.04f)));
    EXPECT_EQ(scene.triangles[1].p[2], glm::dvec3(glm::vec3(-0.99f, 0.0f, -1.04f)));
    const Material &floorMaterial = scene.materials[floor.material];
    EXPECT_EQ(floorMaterial.name, prefix + "floor");
    EXPECT_EQ(floorMaterial.color, glm::vec3(0.725f, 0.71f, 0.68f));
    EXPECT_EQ(floorMaterial.ior, 1.0f);
    EXPECT_EQ(floorMaterial.shininess, 10.0f);
    EXPECT_EQ(floorMaterial.specular, 0.0f);
    for (const Material &m : scene.materials)
        if (m.name == prefix + "leftWall") {
            EXPECT_EQ(m.color, glm::vec3(0.63f, 0.065f, 0.05f));
            EXPECT_EQ(m.ior, 1.5f);
        }
    for (const Triangle &t : scene.triangles) {
        EXPECT_EQ(t.shading, kNoShading);
        EXPECT_NE(t.material, 0u);
    }
}

TEST(ModelAssets, SpiderBackslashTexturesAndDegenerateTriangles) {
    Scene scene = modelsScene("mesh spider/spider.obj scale 0.01\n");
    EXPECT_EQ(scene.triangles.size(), 1368u - 56u);
    ASSERT_EQ(scene.warnings.size(), 1u) << allWarnings(scene);
    EXPECT_NE(scene.warnings[0].find(":1: warning: 56 degenerate (zero-area) triangles in '"),
              std::string::npos)
        << scene.warnings[0];
    ASSERT_EQ(scene.materials.size(), 5u); // default + the 4 materials faces use
    ASSERT_EQ(scene.textures.size(), 4u);  // Brusttex's wal69ar_small.jpg is never loaded
    std::set<std::string> textureFiles;
    for (const Texture &t : scene.textures) {
        textureFiles.insert(std::filesystem::path(t.path).filename().string());
        EXPECT_EQ(t.texels.size(), size_t(t.width) * size_t(t.height));
    }
    EXPECT_EQ(textureFiles, (std::set<std::string>{"wal67ar_small.jpg", "SpiderTex.jpg",
                                                   "drkwood2.jpg", "engineflare1.jpg"}));
    for (size_t i = 1; i < scene.materials.size(); ++i)
        EXPECT_NE(scene.materials[i].texture, kNoTexture) << scene.materials[i].name;
    std::set<uint32_t> used;
    for (size_t i = 0; i < scene.triangles.size(); ++i) {
        used.insert(scene.triangles[i].material);
        TriangleShading s = scene.shadingOf(i);
        EXPECT_TRUE(s.hasUVs);
        EXPECT_TRUE(s.hasNormals);
        EXPECT_NEAR(glm::length(s.n[0]), 1.0f, 1e-6f);
    }
    EXPECT_EQ(used, (std::set<uint32_t>{1, 2, 3, 4}));
}

TEST(ModelAssets, SpotHasUvsEverywhereAndTakesATextureFromAMaterialLine) {
    Scene scene = modelsScene("material cow texture spot/spot_texture.png specular 0.2\n"
                              "mesh spot/spot_triangulated.obj cow rotate y 180\n");
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    ASSERT_EQ(scene.triangles.size(), 5856u);
    for (size_t i = 0; i < scene.triangles.size(); ++i) {
        EXPECT_TRUE(scene.shadingOf(i).hasUVs);
        EXPECT_FALSE(scene.shadingOf(i).hasNormals);
        EXPECT_EQ(scene.triangles[i].material, 1u);
    }
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].width, 1024);
    EXPECT_EQ(scene.textures[0].height, 1024);
    EXPECT_EQ(scene.materials[1].texture, 0);
}

TEST(ModelAssets, BunnyAndTeapotTriangleCounts) {
    Scene scene = modelsScene("mesh bunny/bunny_lowres.obj\nmesh teapot/teapot.obj\n");
    EXPECT_TRUE(scene.warnings.empty()) << allWarnings(scene);
    EXPECT_EQ(scene.triangles.size(), 4968u + 6320u);
}

// A 70k-triangle OBJ must load well under a second in an optimised build.
TEST(ModelAssets, SeventyThousandTrianglesLoadQuickly) {
    test::TempDir dir;
    constexpr int kSide = 188; // 187^2 quads = 69938 triangles
    std::ostringstream obj;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i)
            obj << "v " << i * 0.013 << ' ' << std::sin(i * 0.1) * std::cos(j * 0.1) << ' '
                << j * 0.017 << '\n';
    for (int j = 0; j + 1 < kSide; ++j)
        for (int i = 0; i + 1 < kSide; ++i) {
            int a = j * kSide + i + 1;
            obj << "f " << a << ' ' << a + 1 << ' ' << a + kSide + 1 << ' ' << a + kSide << '\n';
        }
    dir.write("grid.obj", obj.str());
    std::filesystem::path scene = dir.write("s.scene", "mesh grid.obj scale 2 rotate y 30\n");
    Timer timer;
    Scene loaded = loadScene(scene);
    double ms = timer.elapsedMs();
    EXPECT_EQ(loaded.triangles.size(), 187u * 187u * 2u);
    RecordProperty("load_ms", std::to_string(ms));
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
    EXPECT_LT(ms, 1000.0);
#endif
}

} // namespace
} // namespace prism
