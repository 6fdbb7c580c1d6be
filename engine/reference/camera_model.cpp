#include "reference/camera_model.h"

#include <cmath>

#include "shared/sampling.h"

namespace prism {

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
