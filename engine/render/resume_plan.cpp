#include "render/resume_plan.h"

#include <algorithm>

#include "shared/gpu_types.h"

namespace prism {

uint64_t ResumePlan::recordBytes() const {
    return uint64_t(tileWidth) * tileHeight * sizeof(gpu::GpuResumeRecord);
}

uint64_t ResumePlan::logBytes() const {
    return uint64_t(tileWidth) * tileHeight * walkLogSize * 16u;
}

ResumePlan planResume(uint32_t width, uint32_t height, uint32_t maxDepth, uint32_t lights,
                      bool writeAov, uint64_t memoryBytes) {
    uint64_t rays = (uint64_t(1) << std::min(maxDepth, 16u)) - 1u;
    uint64_t walks = rays * (1u + uint64_t(lights)) + (writeAov ? 1u : 0u);
    ResumePlan plan;
    plan.walkLogSize = uint32_t(std::min<uint64_t>(walks, kMaxWalkLog));
    auto roundUp8 = [](uint32_t n) { return (std::max(n, 1u) + 7u) / 8u * 8u; };
    plan.tileWidth = roundUp8(width);
    plan.tileHeight = roundUp8(height);
    uint64_t perPixel = sizeof(gpu::GpuResumeRecord) + 16u * uint64_t(plan.walkLogSize);
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
