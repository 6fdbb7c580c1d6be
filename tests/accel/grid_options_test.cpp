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

} // namespace
} // namespace prism
