#include "scene/camera_frame.h"

#include <cmath>

namespace prism {

CameraFrame makeCameraFrame(const Camera &camera, int width, int height) {
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

} // namespace prism
