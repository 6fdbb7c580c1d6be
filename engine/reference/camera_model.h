#pragma once
// The scene format's camera model (docs/scene-format.md, "Camera model") in double precision:
// where the CPU reference's primary rays start and which way they go.
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/camera_frame.h"
#include "scene/scene.h"

namespace prism {

struct Ray {
    glm::dvec3 origin, dir; // dir is unit length
};

// The ray through a point of the image; pixelPosition is in pixels, (0, 0) the top-left corner.
Ray cameraRay(const CameraFrame &frame, glm::dvec2 pixelPosition);

// Where sample `sampleIndex` of `spp` falls in pixel (px, py), in pixels: the centre when
// spp == 1, else a jittered point in its stratum (the shader's samplePosition).
glm::dvec2 pixelSamplePosition(int px, int py, uint32_t pixelIndex, uint32_t sampleIndex,
                               uint32_t spp);

} // namespace prism
