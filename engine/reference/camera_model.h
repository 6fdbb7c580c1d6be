#pragma once
// The scene format's camera model (docs/scene-format.md, "Camera model") in double precision:
// where the CPU reference's primary rays start and which way they go.
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

// The camera reduced to what ray generation needs, as the shader's GpuFrameParams but unrounded:
// du is right * (h * a) (perspective) or right * (H / 2) * a (ortho), dv is trueUp * h or H / 2.
struct CameraFrame {
    glm::dvec3 eye, forward, du, dv;
    bool ortho;
    int width, height;
};

CameraFrame makeCameraFrame(const Camera &camera, int width, int height);

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
