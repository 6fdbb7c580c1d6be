#pragma once
// The scene format's camera model (docs/scene-format.md, "Camera model") reduced to what ray
// generation needs, in double precision. The shader's frame parameters are this rounded once to
// float; the CPU reference uses it as is.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

// du is right * (h * a) (perspective, h = tan(fov / 2)) or right * (H / 2) * a (ortho); dv is
// trueUp * h or trueUp * H / 2. A pixel position (x, y) in [-1, 1]^2 maps to the direction
// forward + x du + y dv (perspective) or the origin eye + x du + y dv (ortho).
struct CameraFrame {
    glm::dvec3 eye, forward, du, dv;
    bool ortho;
    int width, height;
};

CameraFrame makeCameraFrame(const Camera &camera, int width, int height);

} // namespace prism
