// The shared sample numbers (shaders/shared/sampling.h): stratified area-light pairs put each
// of a pixel's samples in its own stratum.
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "shared/sampling.h"

namespace prism::gpu {
namespace {

TEST(StratifiedPair, EverySampleOfAPixelInItsOwnGridCell) {
    for (uint spp : {4u, 9u, 16u, 12u}) {
        uint columns = strataColumns(spp), rows = strataRows(spp);
        ASSERT_EQ(columns * rows, spp);
        for (uint pixel : {0u, 17u, 123456u}) {
            std::set<std::pair<uint, uint>> cells;
            for (uint s = 0; s < spp; ++s) {
                vec2 u = stratifiedPair(pixel, s, spp, 7u);
                ASSERT_GE(u.x, 0.0f);
                ASSERT_LT(u.x, 1.0f);
                ASSERT_GE(u.y, 0.0f);
                ASSERT_LT(u.y, 1.0f);
                cells.insert({uint(u.x * float(columns)), uint(u.y * float(rows))});
            }
            EXPECT_EQ(cells.size(), spp) << "spp " << spp << " pixel " << pixel;
        }
    }
}

TEST(StratifiedPair, OtherCountsUseStrips) {
    for (uint spp : {2u, 3u, 5u, 7u}) {
        std::set<uint> strips;
        for (uint s = 0; s < spp; ++s)
            strips.insert(uint(stratifiedPair(42u, s, spp, 3u).y * float(spp)));
        EXPECT_EQ(strips.size(), spp) << "spp " << spp;
    }
}

// The stratum a sample gets is rotated per pixel, so the light strata do not follow the pixel
// jitter strata in lockstep across the image.
TEST(StratifiedPair, StratumOrderDiffersBetweenPixels) {
    int differentFirstStratum = 0;
    for (uint pixel = 0; pixel < 64; ++pixel)
        differentFirstStratum += uint(stratifiedPair(pixel, 0u, 16u, 2u).x * 4.0f) !=
                                 uint(stratifiedPair(0u, 0u, 16u, 2u).x * 4.0f);
    EXPECT_GT(differentFirstStratum, 20);
}

} // namespace
} // namespace prism::gpu
