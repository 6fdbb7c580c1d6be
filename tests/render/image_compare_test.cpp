// The image comparison itself (image_compare.h): a test that compares nothing must not pass.
#include <cmath>
#include <limits>
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

// A NaN or an infinity never matches: where both images have one the pixel differs, and where
// only one does the mean is infinite, so that neither a bound on the count nor one on the mean
// lets the image through.
TEST(ImageCompare, NonFiniteChannelsDifferAndFailTheMean) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> finite = {0.5f, 0.5f, 0.5f, 1.0f, 0.2f, 0.2f, 0.2f, 1.0f};
    for (float bad : {nan, inf, -inf}) {
        std::vector<float> broken = finite;
        broken[1] = bad;
        for (const ImageDifference &d :
             {compareImages(broken, finite, 0.5), compareImages(finite, broken, 0.5)}) {
            EXPECT_EQ(d.nonFinite, 1u);
            EXPECT_EQ(d.differing, 1u);
            EXPECT_FALSE(std::isfinite(d.meanAbsolute));
            EXPECT_FALSE(std::isfinite(d.largest));
        }
        // Both broken alike: still a differing pixel, though the mean of the rest stays finite.
        ImageDifference both = compareImages(broken, broken, 0.5);
        EXPECT_EQ(both.nonFinite, 1u);
        EXPECT_EQ(both.differing, 1u);
        EXPECT_TRUE(std::isfinite(both.meanAbsolute));
    }
    // Nothing non-finite, nothing differs.
    ImageDifference same = compareImages(finite, finite, 0.0);
    EXPECT_EQ(same.nonFinite, 0u);
    EXPECT_EQ(same.differing, 0u);
}

} // namespace
} // namespace prism::test
