// The image comparison itself (image_compare.h): a test that compares nothing must not pass.
#include <vector>

#include <gtest/gtest.h>

#include "image_compare.h"

namespace prism::test {
namespace {

TEST(ImageCompare, CountsPixelsOverTheThresholdAndIgnoresAlpha) {
    std::vector<float> a = {0.5f, 0.5f, 0.5f, 1.0f, 0.1f, 0.2f, 0.3f, 1.0f};
    std::vector<float> b = {0.5f, 0.5f, 0.6f, 0.0f, 0.1f, 0.2f, 0.3f, 0.0f};
    ImageDifference d = compareImages(a, b, 0.05);
    EXPECT_EQ(d.pixels, 2u);
    EXPECT_EQ(d.differing, 1u);
    EXPECT_NEAR(d.largest, 0.1, 1e-6);
}

TEST(ImageCompare, TruncatedOrEmptyImagesDifferEverywhere) {
    std::vector<float> whole(4 * 6, 0.25f), truncated(4 * 5, 0.25f), empty;
    for (const ImageDifference &d :
         {compareImages(whole, truncated, 0.02), compareImages(truncated, whole, 0.02),
          compareImages(empty, empty, 0.02)}) {
        EXPECT_TRUE(d.sizesDiffer);
        EXPECT_GT(d.differing, 0u);
        EXPECT_EQ(d.differingFraction(), 1.0);
        EXPECT_GT(d.meanAbsolute, 1.0);
    }
    EXPECT_FALSE(compareImages(whole, whole, 0.02).sizesDiffer);
}

} // namespace
} // namespace prism::test
