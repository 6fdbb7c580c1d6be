// The shared sample numbers (shaders/shared/sampling.h): stratified area-light pairs put each
// of a pixel's samples in its own stratum; a sampling seed gives every pixel samples of its own.
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

// A seed other than 0 gives each pixel its own key (no two pixels of a 1024x768 image share
// their samples), seed 0 keeps the pixel index (the images made before seeds), and two seeds
// agree on almost no pixel.
TEST(SamplingKey, EachSeedGivesEveryPixelItsOwnSamples) {
    const uint pixels = 1024u * 768u;
    for (uint seed : {1u, 2u, 16777215u}) {
        std::set<uint> keys;
        for (uint p = 0; p < pixels; ++p)
            keys.insert(samplingKey(p, seed));
        EXPECT_EQ(keys.size(), size_t(pixels)) << "seed " << seed;
    }
    for (uint p : {0u, 1u, 4095u, 33177599u})
        EXPECT_EQ(samplingKey(p, 0u), p);
    size_t same = 0;
    for (uint p = 0; p < pixels; ++p)
        same += samplingKey(p, 1u) == samplingKey(p, 2u) || samplingKey(p, 1u) == p ? 1 : 0;
    EXPECT_LE(same, 2u);
}

} // namespace
} // namespace prism::gpu
