// planResume: tiles of whole workgroups that fit the memory budget, logs that hold every walk
// a sample can make (up to kMaxWalkLog).
#include <gtest/gtest.h>

#include "render/resume_plan.h"

namespace prism {
namespace {

TEST(ResumePlan, LogHoldsEveryWalkOfTheRayTree) {
    // depth 3, glass that also reflects (3 rays a hit): 1 + 3 + 9 rays, each with a closest-hit
    // walk and one shadow walk per light, + the AOV walk
    EXPECT_EQ(planResume(64, 64, 3, 2, true).walkLogSize, 13u * 3u + 1u);
    // mirrors only (1 ray a hit), glass only (2)
    EXPECT_EQ(planResume(64, 64, 3, 2, true, 64 << 20, false, 1).walkLogSize, 3u * 3u + 1u);
    EXPECT_EQ(planResume(64, 64, 3, 2, true, 64 << 20, false, 2).walkLogSize, 7u * 3u + 1u);
    EXPECT_EQ(planResume(64, 64, 1, 1, false).walkLogSize, 2u);
    EXPECT_EQ(planResume(64, 64, 30, 4, false).walkLogSize, kMaxWalkLog);
}

TEST(ResumePlan, InstancesLogTwiceTheBytes) {
    ResumePlan plain = planResume(64, 64, 3, 2, true);
    ResumePlan instanced = planResume(64, 64, 3, 2, true, 64 << 20, true);
    EXPECT_EQ(instanced.logBytes(), 2 * plain.logBytes());
}

TEST(ResumePlan, SmallImagesAreOneTileOfWholeWorkgroups) {
    ResumePlan plan = planResume(30, 17, 5, 1, false);
    EXPECT_EQ(plan.tileWidth, 32u);
    EXPECT_EQ(plan.tileHeight, 24u);
}

TEST(ResumePlan, TilesFitTheMemoryBudget) {
    for (uint64_t budget : {uint64_t(1) << 20, uint64_t(8) << 20, uint64_t(64) << 20}) {
        ResumePlan plan = planResume(4096, 3000, 8, 3, true, budget);
        SCOPED_TRACE(budget);
        EXPECT_LE(plan.recordBytes() + plan.logBytes(), budget);
        EXPECT_EQ(plan.tileWidth % 8, 0u);
        EXPECT_EQ(plan.tileHeight % 8, 0u);
        EXPECT_GE(plan.tileWidth, 8u);
        EXPECT_GE(plan.tileHeight, 8u);
    }
    // A budget too small for even one workgroup still gets one (8x8) tile.
    ResumePlan tiny = planResume(100, 100, 8, 3, false, 1);
    EXPECT_EQ(tiny.tileWidth, 8u);
    EXPECT_EQ(tiny.tileHeight, 8u);
}

} // namespace
} // namespace prism
