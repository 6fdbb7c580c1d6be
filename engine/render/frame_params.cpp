#include "render/frame_params.h"

#include <cmath>

namespace prism {

gpu::GpuFrameParams makeFrameParams(const Camera &camera, uint32_t width, uint32_t height,
                                    uint32_t samplesPerPixel, uint32_t maxDepth) {
    glm::dvec3 eye(camera.eye), look(camera.look), up(camera.up);
    glm::dvec3 forward = glm::normalize(look - eye);
    glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    glm::dvec3 trueUp = glm::cross(right, forward);
    double aspect = double(width) / double(height);
    // Half the image plane's height at unit distance (perspective) or in world units (ortho).
    double halfHeight = camera.isOrtho() ? 0.5 * double(camera.orthoHeight)
                                         : std::tan(glm::radians(double(camera.fovDegrees)) * 0.5);
    gpu::GpuFrameParams p{};
    p.eye = glm::vec4(glm::vec3(eye), camera.isOrtho() ? 1.0f : 0.0f);
    p.forward = glm::vec4(glm::vec3(forward), 0.0f);
    p.du = glm::vec4(glm::vec3(right * (halfHeight * aspect)), 0.0f);
    p.dv = glm::vec4(glm::vec3(trueUp * halfHeight), 0.0f);
    p.image = glm::uvec4(width, height, 0u, samplesPerPixel);
    p.control = glm::uvec4(maxDepth, 1u, 0u, 0u);
    return p;
}

} // namespace prism
