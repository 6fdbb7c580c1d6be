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

TEST(GridOptions, ExpansionSpellings) {
    EXPECT_EQ(parseGridExpansion("auto"), GridOptions::Expansion::Auto);
    EXPECT_EQ(parseGridExpansion("always"), GridOptions::Expansion::Always);
    EXPECT_EQ(parseGridExpansion("never"), GridOptions::Expansion::Never);
    for (const char *bad : {"", "Auto", "yes", "always "}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(parseGridExpansion(bad), Error);
    }
}

// auto expands where the camera samples reach kExpansionSamplesPerPrimitive a primitive, and
// where they are unknown (0: a viewer, a Python session); always and never do as they say.
TEST(GridOptions, ExpansionFollowsTheSamplesAPrimitive) {
    GridOptions o;
    EXPECT_EQ(o.expansion, GridOptions::Expansion::Auto);
    EXPECT_TRUE(expandsCells(o, 1'000'000)) << "unknown samples: expanded";
    const uint64_t primitives = 1'000'000;
    const auto threshold = uint64_t(kExpansionSamplesPerPrimitive * double(primitives));
    o.cameraSamples = 512 * 384; // one image of a 1M-triangle mesh
    EXPECT_FALSE(expandsCells(o, primitives));
    o.cameraSamples = threshold - 1;
    EXPECT_FALSE(expandsCells(o, primitives));
    o.cameraSamples = threshold;
    EXPECT_TRUE(expandsCells(o, primitives));
    o.cameraSamples = 1024 * 768; // the same image of a small scene
    EXPECT_TRUE(expandsCells(o, 12'184));
    o.cameraSamples = 1;
    o.expansion = GridOptions::Expansion::Always;
    EXPECT_TRUE(expandsCells(o, primitives));
    o.cameraSamples = 0;
    o.expansion = GridOptions::Expansion::Never;
    EXPECT_FALSE(expandsCells(o, 10));
}

} // namespace
} // namespace prism
