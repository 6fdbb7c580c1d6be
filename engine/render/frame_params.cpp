#include "render/frame_params.h"

#include "scene/camera_frame.h"

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
    return p;
}

} // namespace prism
