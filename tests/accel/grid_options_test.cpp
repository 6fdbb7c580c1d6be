// --grid's argument: every accepted spelling and every way it can be wrong.
#include <gtest/gtest.h>

#include "accel/grid.h"
#include "core/error.h"

namespace prism {
namespace {

TEST(GridOptions, AutoAndOff) {
    EXPECT_EQ(parseGridOption("auto").mode, GridOptions::Mode::Auto);
    EXPECT_EQ(parseGridOption("two-level").mode, GridOptions::Mode::TwoLevel);
    EXPECT_EQ(parseGridOption("off").mode, GridOptions::Mode::Off);
}

TEST(GridOptions, CubeAndPerAxisCounts) {
    GridOptions cube = parseGridOption("10");
    EXPECT_EQ(cube.mode, GridOptions::Mode::Fixed);
    EXPECT_EQ(cube.resolution, glm::ivec3(10));
    GridOptions box = parseGridOption("4x8x2");
    EXPECT_EQ(box.mode, GridOptions::Mode::Fixed);
    EXPECT_EQ(box.resolution, glm::ivec3(4, 8, 2));
    EXPECT_EQ(parseGridOption("1024x1x1").resolution, glm::ivec3(1024, 1, 1));
}

TEST(GridOptions, RejectsBadText) {
    for (const char *bad : {"", "0", "-3", "1025", "ten", "4x4", "4x4x", "x4x4", "4x4x4x4", "4.5",
                            "4 ", "Auto", "256x256x257"}) {
        SCOPED_TRACE(bad);
        try {
            parseGridOption(bad);
            ADD_FAILURE() << "accepted";
        } catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find("--grid"), std::string::npos) << e.what();
        }
    }
}

TEST(GridOptions, BuildSpellings) {
    EXPECT_EQ(parseGridBuild("auto"), GridOptions::Effort::Auto);
    EXPECT_EQ(parseGridBuild("full"), GridOptions::Effort::Full);
    EXPECT_EQ(parseGridBuild("lean"), GridOptions::Effort::Lean);
    for (const char *bad : {"", "Auto", "fast", "lean "}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(parseGridBuild(bad), Error);
    }
}

// auto builds lean where the camera samples are under kLeanBelowSamplesPerPrimitive a primitive,
// and full where they reach it or are unknown (0: a viewer, a Python session); full and lean do
// as they say.
TEST(GridOptions, BuildEffortFollowsTheSamplesAPrimitive) {
    GridOptions o;
    EXPECT_EQ(o.effort, GridOptions::Effort::Auto);
    EXPECT_FALSE(buildsLean(o, 1'000'000)) << "unknown samples: full";
    const uint64_t primitives = 1'000'000;
    const auto threshold = uint64_t(kLeanBelowSamplesPerPrimitive * double(primitives));
    o.cameraSamples = 512 * 384; // one image of a 1M-triangle mesh
    EXPECT_TRUE(buildsLean(o, primitives));
    o.cameraSamples = threshold - 1;
    EXPECT_TRUE(buildsLean(o, primitives));
    o.cameraSamples = threshold;
    EXPECT_FALSE(buildsLean(o, primitives));
    o.cameraSamples = 1024 * 768; // the same image of a small scene
    EXPECT_FALSE(buildsLean(o, 12'184));
    o.cameraSamples = 1;
    o.effort = GridOptions::Effort::Full;
    EXPECT_FALSE(buildsLean(o, primitives));
    o.cameraSamples = 0;
    o.effort = GridOptions::Effort::Lean;
    EXPECT_TRUE(buildsLean(o, 10));
}

} // namespace
} // namespace prism
