#include "reference/camera_model.h"

#include <cmath>

#include "shared/sampling.h"

namespace prism {

CameraFrame makeCameraFrame(const Camera &camera, int width, int height) {
    // Same basis as engine/render/frame_params.cpp, kept in double.
    glm::dvec3 eye(camera.eye), look(camera.look), up(camera.up);
    glm::dvec3 forward = glm::normalize(look - eye);
    glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    glm::dvec3 trueUp = glm::cross(right, forward);
    double aspect = double(width) / double(height);
    // Half the image plane's height at unit distance (perspective) or in world units (ortho).
    double halfHeight = camera.isOrtho() ? 0.5 * double(camera.orthoHeight)
                                         : std::tan(glm::radians(double(camera.fovDegrees)) * 0.5);
    CameraFrame frame;
    frame.eye = eye;
    frame.forward = forward;
    frame.du = right * (halfHeight * aspect);
    frame.dv = trueUp * halfHeight;
    frame.ortho = camera.isOrtho();
    frame.width = width;
    frame.height = height;
    return frame;
}

Ray cameraRay(const CameraFrame &frame, glm::dvec2 pixelPosition) {
    glm::dvec2 uv = pixelPosition / glm::dvec2(frame.width, frame.height);
    double x = 2.0 * uv.x - 1.0, y = 1.0 - 2.0 * uv.y;
    if (frame.ortho) // parallel rays leave the image plane
        return {frame.eye + x * frame.du + y * frame.dv, frame.forward};
    return {frame.eye, glm::normalize(frame.forward + x * frame.du + y * frame.dv)};
}

glm::dvec2 pixelSamplePosition(int px, int py, uint32_t pixelIndex, uint32_t sampleIndex,
                               uint32_t spp) {
    glm::dvec2 pixel(px, py);
    if (spp <= 1u)
        return pixel + 0.5;
    // Stratified jitter with the shader's hash (shaders/shared/sampling.h), so both trace the
    // same sample positions.
    uint32_t columns = gpu::strataColumns(spp), rows = gpu::strataRows(spp);
    glm::dvec2 stratum(sampleIndex % columns, sampleIndex / columns);
    glm::dvec2 jitter(gpu::sample01(pixelIndex, sampleIndex, PRISM_DIM_PIXEL_X),
                      gpu::sample01(pixelIndex, sampleIndex, PRISM_DIM_PIXEL_Y));
    return pixel + (stratum + jitter) / glm::dvec2(columns, rows);
}

} // namespace prism
