// Moving instances (format 1.2, keyed placements): a frame traces the instances where the keys
// put them, through the same tracer with only the instance level of its grid built again
// (session/prepared_scene.h: moveToFrame; RayTracer::setScene). Held to the still scene whose
// place lines carry the last keys' values, bit for bit, on assets/scenes/moving-instances.scene.
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "read_file.h"
#include "render/ray_tracer.h"
#include "scene/scene_loader.h"
#include "session/prepared_scene.h"

namespace prism::test {
namespace {

const std::filesystem::path kMoving = std::filesystem::path(PRISM_SCENES_DIR) /
                                      "moving-instances.scene";
constexpr uint32_t kWidth = 64, kHeight = 48, kSpp = 2;
const GridOptions kRegular{GridOptions::Mode::Regular};

// moving-instances.scene with every keyed place line at its last key's values, and no keys.
Scene stillAtTheLastKeys() {
    std::string text = readFile(kMoving);
    text = std::regex_replace(text, std::regex("\nkey [^\n]*"), "");
    auto replace = [&](const std::string &from, const std::string &to) {
        size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("place bunny scale 0.8 rotate y 180 translate -2.7 0 -1",
            "place bunny scale 0.8 rotate y 90 translate 1.2 0 -0.6");
    replace("place teapot rust rotate y 0 translate 2.3 0 1",
            "place teapot rust rotate y 360 translate 2.3 0 1");
    replace("place bunny jade scale 0.5 rotate y 20", "place bunny jade scale 1 rotate y 20");
    return parseScene(text, kMoving); // meshes resolve beside the real file
}

TracedImage render(RayTracer &tracer, const Camera &camera) {
    tracer.renderFrame(camera, kSpp);
    return tracer.readback(kSpp);
}

class MovingInstances : public GpuTest {};

TEST_F(MovingInstances, OnlyTheInstanceLevelIsBuiltAgainAndHeldFramesCostNothing) {
    PreparedScene prepared = prepareScene(loadScene(kMoving), kRegular, nullptr);
    ASSERT_EQ(prepared.grid.meshGrids.size(), 2u);
    const uint32_t *bunnyCells = prepared.grid.meshGrids[0].cellPrimitives.data();
    std::vector<uint32_t> firstLevel = prepared.grid.cellPrimitives;
    glm::vec3 firstMin = prepared.grid.boundsMin;
    EXPECT_FALSE(moveToFrame(prepared, 1.0)) << "already at frame 1";
    EXPECT_TRUE(moveToFrame(prepared, 13.0));
    EXPECT_EQ(prepared.grid.meshGrids[0].cellPrimitives.data(), bunnyCells)
        << "the bunny's own grid is the one built at frame 1, not a copy or a rebuild";
    EXPECT_TRUE(prepared.grid.boundsMin != firstMin || prepared.grid.cellPrimitives != firstLevel)
        << "the instance level follows the instances";
    EXPECT_TRUE(moveToFrame(prepared, 48.0));
    EXPECT_FALSE(moveToFrame(prepared, 60.0)) << "after the last key nothing moves";
    EXPECT_TRUE(moveToFrame(prepared, 1.0)) << "back to frame 1";
    EXPECT_EQ(prepared.grid.cellPrimitives, firstLevel);

    PreparedScene still = prepareScene(stillAtTheLastKeys(), kRegular, nullptr);
    EXPECT_FALSE(moveToFrame(still, 48.0)) << "a scene without keys never moves";
}

TEST_F(MovingInstances, AFrameIsTheStillSceneAtItsKeysBitForBit) {
    PreparedScene moving = prepareScene(loadScene(kMoving), kRegular, nullptr);
    RayTracer tracer(context(), moving.scene, moving.grid, kWidth, kHeight, {});
    TracedImage first = render(tracer, moving.scene.camera);
    ASSERT_TRUE(moveToFrame(moving, 13.0));
    tracer.setScene(moving.scene, moving.grid);
    TracedImage between = render(tracer, moving.scene.camera);
    ASSERT_TRUE(moveToFrame(moving, 48.0));
    tracer.setScene(moving.scene, moving.grid);
    TracedImage last = render(tracer, moving.scene.camera);

    PreparedScene still = prepareScene(stillAtTheLastKeys(), kRegular, nullptr);
    RayTracer stillTracer(context(), still.scene, still.grid, kWidth, kHeight, {});
    TracedImage expected = render(stillTracer, still.scene.camera);
    EXPECT_EQ(last.rgba, expected.rgba) << "frame 48 is the still scene at the last keys";
    EXPECT_NE(first.rgba, last.rgba);
    EXPECT_NE(between.rgba, first.rgba);
    EXPECT_NE(between.rgba, last.rgba);

    // Back at frame 1 the tracer draws frame 1 again.
    ASSERT_TRUE(moveToFrame(moving, 1.0));
    tracer.setScene(moving.scene, moving.grid);
    EXPECT_EQ(render(tracer, moving.scene.camera).rgba, first.rgba);
}

} // namespace
} // namespace prism::test
