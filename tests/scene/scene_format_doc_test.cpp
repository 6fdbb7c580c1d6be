// docs/scene-format.md as a newcomer uses it: the page's first example, saved in a folder of its
// own, loads as it says; and the mesh line its text gives for a scene in assets/scenes/ loads the
// bunny from there (paths are relative to the scene file, not to where the command runs).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace prism::test {
namespace {

std::string page() {
    std::ifstream in(std::string(PRISM_DOCS_DIR) + "/scene-format.md");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(SceneFormatPage, FirstExampleLoadsFromAnyFolder) {
    std::string text = page();
    size_t open = text.find("```\n"), close = text.find("```\n", open + 4);
    ASSERT_NE(open, std::string::npos);
    ASSERT_NE(close, std::string::npos);
    TempDir dir;
    std::filesystem::path file = dir.write("balls.scene", text.substr(open + 4, close - open - 4));
    Scene scene = loadScene(file);
    EXPECT_EQ(scene.spheres.size(), 2u);
    EXPECT_EQ(scene.planes.size(), 1u);
    EXPECT_EQ(scene.lights.size(), 1u);
}

TEST(SceneFormatPage, ItsMeshLineLoadsFromTheScenesFolder) {
    // Found by hand, not std::regex: GCC 12 warns inside <regex> under the sanitizers (-Werror).
    std::string text = page();
    size_t at = text.find("`mesh ../models/");
    ASSERT_NE(at, std::string::npos);
    size_t end = text.find('`', at + 1);
    ASSERT_NE(end, std::string::npos);
    std::string scene =
        "material red color 0.9 0.1 0.1\n" + text.substr(at + 1, end - at - 1) + "\n";
    Scene loaded = parseScene(scene, std::string(PRISM_ASSETS_DIR) + "/scenes/page.scene");
    EXPECT_EQ(loaded.triangles.size(), 4968u);   // the bunny
    EXPECT_TRUE(loaded.shadingOf(0).hasNormals); // `smooth`
}

} // namespace
} // namespace prism::test
