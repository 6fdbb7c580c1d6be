// RayTracer's resumable frames (shaders/resume.glsl): a sample that overruns lavapipe's loop
// limit is traced tile by tile, each tile dispatched again and again until every pixel's sample
// is finished. Each dispatch is its own submission: the host reads how many pixels are left.
#include <algorithm>
#include <cstddef>
#include <string>

#include "core/error.h"
#include "core/timer.h"
#include "render/frame_params.h"
#include "render/ray_tracer.h"
#include "shared/trace_interface.h"
#include "vk/barriers.h"

namespace prism {
namespace {

// Compute writes of one submission made visible to the next one's fills and shader reads.
void afterEarlierDispatches(VkCommandBuffer commands) {
    VkPipelineStageFlags stages =
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    vk::memoryBarrier(
        commands, stages, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, stages,
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
}

} // namespace

void RayTracer::startResuming() {
    vkDeviceWaitIdle(context_.device());
    resumePlan_ = planResume(storeWidth_, storeHeight_, features_.maxDepth, lightCount_, features_.writeAov,
                             resumeMemoryBytes_, features_.has(gpu::kKindInstance),
                             (features_.reflection ? 1u : 0u) + (features_.transmission ? 2u : 0u));
    resumeRecords_ =
        vk::Buffer(context_, resumePlan_.recordBytes(),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    walkLog_ =
        vk::Buffer(context_, resumePlan_.logBytes(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    features_.resumable = true;
    createPipeline();
}

void RayTracer::traceSampleResumably(const Camera &camera, uint32_t sample,
                                     uint32_t samplesPerPixel, bool resetCounters,
                                     FrameResult &result) {
    copiedOut_ = false;
    const ResumePlan &plan = resumePlan_;
    // The plan's tiles over the region's 8x8 tiles (the whole image without a region).
    uint32_t originX = window_.x0 * kTileSize, originY = window_.y0 * kTileSize;
    uint32_t tilesX = (storeWidth_ + plan.tileWidth - 1) / plan.tileWidth;
    uint32_t tilesY = (storeHeight_ + plan.tileHeight - 1) / plan.tileHeight;
    gpu::GpuFrameParams params = frameParams(camera, samplesPerPixel);
    params.control.w = plan.walkLogSize;
    setFrameSample(params, sample);
    const auto *counters = static_cast<const gpu::GpuStats *>(stats_.mapped());
    for (uint32_t ty = 0; ty < tilesY; ++ty) {
        for (uint32_t tx = 0; tx < tilesX; ++tx) {
            uint32_t x0 = tx * plan.tileWidth, y0 = ty * plan.tileHeight;
            params.control.z = (originX + x0) | ((originY + y0) << 16u);
            uint32_t groupsX = (std::min(plan.tileWidth, storeWidth_ - x0) + 7) / 8;
            uint32_t groupsY = (std::min(plan.tileHeight, storeHeight_ - y0) + 7) / 8;
            for (bool fresh = true;; fresh = false) {
                Timer hostTimer;
                runner_.run([&](VkCommandBuffer commands) {
                    timestamps_.recordReset(commands);
                    afterEarlierDispatches(commands);
                    if (resetCounters)
                        vkCmdFillBuffer(commands, stats_.handle(), 0, VK_WHOLE_SIZE, 0);
                    else
                        vkCmdFillBuffer(commands, stats_.handle(),
                                        offsetof(gpu::GpuStats, unfinishedPixels), 16, 0);
                    if (fresh) // a new sample of this tile: every pixel starts again
                        vkCmdFillBuffer(commands, resumeRecords_.handle(), 0, VK_WHOLE_SIZE, 0);
                    afterEarlierDispatches(commands);
                    timestamps_.recordStart(commands);
                    pipeline_->bind(commands);
                    recordDispatch(commands, params, groupsX, groupsY);
                    timestamps_.recordEnd(commands);
                    vk::memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                      VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                                      VK_ACCESS_HOST_READ_BIT);
                });
                resetCounters = false;
                double hostMs = hostTimer.elapsedMs();
                result.gpuMs += timestamps_.elapsedMs().value_or(hostMs);
                result.wallMs += hostMs;
                result.resumeDispatches += 1;
                if (counters->stuckPixels > 0)
                    throw Error(std::to_string(counters->stuckPixels) +
                                " pixels cannot be finished by resumable tracing: a sample "
                                "needs more ray walks than it can log (" +
                                std::to_string(plan.walkLogSize) +
                                ") or replay in one dispatch; use a lower --depth" +
                                (features_.has(gpu::kKindInstance)
                                     ? ", or a finer --grid (one instance's walk, which is "
                                       "never split, may be longer than a dispatch allows)"
                                     : ""));
                if (counters->unfinishedPixels == 0)
                    break;
            }
        }
    }
}

FrameResult RayTracer::renderResumable(const Camera &camera, uint32_t samplesPerPixel,
                                       const std::function<void(double)> &progress) {
    enableResumable(); // a tracer asked to resume from the start plans its tiles here
    FrameResult result;
    for (uint32_t sample = 0; sample < samplesPerPixel; ++sample) {
        traceSampleResumably(camera, sample, samplesPerPixel, sample == 0, result);
        if (progress)
            progress(double(sample + 1) / samplesPerPixel);
    }
    FrameResult counted = decodeCounters(stats_.mapped());
    result.rays = counted.rays;
    result.loopCutPixels = counted.loopCutPixels;
    result.tiles = {window_.width() * window_.height(), 0u, 0u};
    lastTileClasses_.clear();
    return result;
}

void RayTracer::enableResumable() {
    if (!features_.resumable || resumePlan_.tileWidth == 0)
        startResuming();
}

FrameResult RayTracer::traceSampleNow(const Camera &camera, uint32_t sample,
                                      uint32_t samplesPerPixel, bool resetCounters) {
    enableResumable();
    FrameResult result;
    traceSampleResumably(camera, sample, samplesPerPixel, resetCounters, result);
    return result;
}

} // namespace prism
