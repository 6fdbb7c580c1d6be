#include "render/resume_plan.h"

#include <algorithm>

#include "shared/gpu_types.h"

namespace prism {

uint64_t ResumePlan::recordBytes() const {
    return uint64_t(tileWidth) * tileHeight * sizeof(gpu::GpuResumeRecord);
}

uint64_t ResumePlan::logBytes() const {
    return uint64_t(tileWidth) * tileHeight * walkLogSize * logEntryBytes;
}

ResumePlan planResume(uint32_t width, uint32_t height, uint32_t maxDepth, uint32_t lights,
                      bool writeAov, uint64_t memoryBytes, bool instances, uint32_t childRays) {
    uint64_t rays = 0, level = 1;
    for (uint32_t d = 0; d < maxDepth && rays < kMaxWalkLog; ++d, level *= childRays)
        rays += level;
    uint64_t walks = rays * (1u + uint64_t(lights)) + (writeAov ? 1u : 0u);
    ResumePlan plan;
    plan.walkLogSize = uint32_t(std::min<uint64_t>(walks, kMaxWalkLog));
    plan.logEntryBytes = instances ? 32u : 16u;
    auto roundUp8 = [](uint32_t n) { return (std::max(n, 1u) + 7u) / 8u * 8u; };
    plan.tileWidth = roundUp8(width);
    plan.tileHeight = roundUp8(height);
    uint64_t perPixel =
        sizeof(gpu::GpuResumeRecord) + uint64_t(plan.logEntryBytes) * plan.walkLogSize;
    while (uint64_t(plan.tileWidth) * plan.tileHeight * perPixel > memoryBytes &&
           (plan.tileWidth > 8 || plan.tileHeight > 8)) {
        if (plan.tileWidth >= plan.tileHeight)
            plan.tileWidth = roundUp8(plan.tileWidth / 2);
        else
            plan.tileHeight = roundUp8(plan.tileHeight / 2);
    }
    return plan;
}

} // namespace prism
