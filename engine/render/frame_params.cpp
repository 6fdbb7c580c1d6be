#include "render/frame_params.h"

#include "scene/camera_frame.h"
#include "shared/sampling.h"

namespace prism {

gpu::GpuFrameParams makeFrameParams(const Camera &camera, uint32_t width, uint32_t height,
                                    uint32_t samplesPerPixel, uint32_t maxDepth) {
    CameraFrame f = makeCameraFrame(camera, int(width), int(height));
    gpu::GpuFrameParams p{};
    p.eye = glm::vec4(glm::vec3(f.eye), f.ortho ? 1.0f : 0.0f);
    p.forward = glm::vec4(glm::vec3(f.forward), 0.0f);
    p.du = glm::vec4(glm::vec3(f.du), 0.0f);
    p.dv = glm::vec4(glm::vec3(f.dv), 0.0f);
    p.image = glm::uvec4(width, height, 0u, samplesPerPixel);
    p.control = glm::uvec4(maxDepth, gpu::kLoopProbeRuns, 0u, 0u);
    setFrameSample(p, 0);
    return p;
}

void setFrameSample(gpu::GpuFrameParams &p, uint32_t sample) {
    uint32_t spp = p.image.w;
    uint32_t columns = gpu::strataColumns(spp), rows = gpu::strataRows(spp);
    p.image.z = sample;
    p.strata =
        glm::vec4(float(sample % columns), float(sample / columns), float(columns), float(rows));
    p.seedsAndLoops.x = gpu::sampleSeed(sample, PRISM_DIM_PIXEL_X);
    p.seedsAndLoops.y = gpu::sampleSeed(sample, PRISM_DIM_PIXEL_Y);
}

} // namespace prism
