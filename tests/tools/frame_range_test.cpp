// --frames lists and per-frame output names (tools/common/frame_range.h).
#include <gtest/gtest.h>

#include "core/error.h"
#include "frame_range.h"

namespace prism {
namespace {

using Frames = std::vector<int>;

void expectListError(const std::string &text, const std::string &fragment) {
    try {
        parseFrameList(text);
        ADD_FAILURE() << "'" << text << "' was accepted";
    } catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
            << "'" << text << "': " << e.what();
    }
}

TEST(FrameRange, ListsRangesAndSteps) {
    EXPECT_EQ(parseFrameList("7"), Frames({7}));
    EXPECT_EQ(parseFrameList("1-4"), Frames({1, 2, 3, 4}));
    EXPECT_EQ(parseFrameList("1-10:3"), Frames({1, 4, 7, 10}));
    EXPECT_EQ(parseFrameList("0-9:4"), Frames({0, 4, 8}));
    EXPECT_EQ(parseFrameList("1,5,10-12"), Frames({1, 5, 10, 11, 12}));
    EXPECT_EQ(parseFrameList("20,3"), Frames({20, 3})); // in the order written
    EXPECT_EQ(parseFrameList("5-5"), Frames({5}));
    EXPECT_EQ(parseFrameList("1-240").size(), 240u);
}

TEST(FrameRange, BadListsSayWhatIsWrong) {
    expectListError("", "the list is empty");
    expectListError("1,,3", "an empty item");
    expectListError("1,", "an empty item");
    expectListError("240-1", "the range '240-1' runs backwards (write it first-last, as 1-240)");
    expectListError("1-10:0", "the step of '1-10:0' must be >= 1");
    expectListError("1-4,3", "frame 3 is listed twice");
    expectListError("-3", "is not a frame");
    expectListError("1.5", "is not a frame");
    expectListError("a-b", "is not a frame");
    expectListError("1-", "is not a frame");
    expectListError("1-10:", "is not a frame");
    expectListError("99999999", "from 0 to 9999999");
    expectListError("0-2000000", "more than 1000000 frames");
}

TEST(FrameRange, OutputPatternsNameTheFrame) {
    EXPECT_EQ(framePath("out/turntable.####.exr", 7), "out/turntable.0007.exr");
    EXPECT_EQ(framePath("t.#.exr", 12), "t.12.exr"); // a longer number is written whole
    EXPECT_EQ(framePath("t.##.exr", 12345), "t.12345.exr");
    EXPECT_EQ(framePath("shot_{frame}.png", 42), "shot_42.png");
    EXPECT_EQ(framePath("still.exr", 3), "still.exr");
    EXPECT_EQ(framePath("take#2/f.###.exr", 5), "take#2/f.005.exr"); // '#' of a directory stays
    EXPECT_TRUE(hasFrameField("a.####.exr"));
    EXPECT_TRUE(hasFrameField("a_{frame}.exr"));
    EXPECT_FALSE(hasFrameField("take#2/a.exr"));
    EXPECT_FALSE(hasFrameField("a.exr"));
}

TEST(FrameRange, AmbiguousPatternsAreErrors) {
    EXPECT_THROW(hasFrameField("a.##.b.##.exr"), Error);
    EXPECT_THROW(hasFrameField("a.##.{frame}.exr"), Error);
    EXPECT_THROW(hasFrameField("{frame}.{frame}.exr"), Error);
    EXPECT_THROW(framePath("a.##.b.##.exr", 1), Error);
}

} // namespace
} // namespace prism
