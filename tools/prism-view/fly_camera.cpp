#include "fly_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace prism {
namespace {

// Rotates v about the unit axis by `radians` (Rodrigues).
glm::vec3 rotate(const glm::vec3 &v, const glm::vec3 &axis, float radians) {
    float c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

} // namespace

FlyCamera::FlyCamera(const Camera &start, float unitsPerSecond)
    : camera_(start), unitsPerSecond_(unitsPerSecond) {}

void FlyCamera::reset(const Camera &start) {
    camera_ = start;
}

void FlyCamera::update(const FlyInput &input, double seconds) {
    glm::vec3 up = glm::normalize(camera_.up);
    glm::vec3 toLook(camera_.look - camera_.eye); // positions are double, directions float
    float focus = glm::length(toLook);
    glm::vec3 forward = toLook / focus;

    if (input.turnPixels != glm::vec2(0.0f)) {
        float yaw = -glm::radians(input.turnPixels.x * kDegreesPerPixel);
        float pitch = -glm::radians(input.turnPixels.y * kDegreesPerPixel);
        forward = rotate(forward, up, yaw);
        // Keep 1 degree away from the up axis, where the camera basis would degenerate.
        float elevation = std::asin(std::clamp(glm::dot(forward, up), -1.0f, 1.0f));
        float limit = glm::radians(89.0f);
        pitch = std::clamp(elevation + pitch, -limit, limit) - elevation;
        glm::vec3 right = glm::normalize(glm::cross(forward, up));
        forward = glm::normalize(rotate(forward, right, pitch));
        camera_.look = camera_.eye + glm::dvec3(forward * focus);
    }
    if (input.move != glm::vec3(0.0f)) {
        glm::vec3 right = glm::normalize(glm::cross(forward, up));
        glm::vec3 step = input.move.x * right + input.move.y * up + input.move.z * forward;
        float distance = unitsPerSecond_ * float(seconds) * (input.fast ? kFastFactor : 1.0f);
        camera_.eye += glm::dvec3(glm::normalize(step) * distance);
        camera_.look = camera_.eye + glm::dvec3(forward * focus);
    }
    if (input.zoomSteps != 0.0f) {
        if (camera_.isOrtho())
            camera_.orthoHeight *= std::pow(0.9f, input.zoomSteps);
        else
            camera_.fovDegrees =
                std::clamp(camera_.fovDegrees - 2.0f * input.zoomSteps, 5.0f, 120.0f);
    }
}

float flySpeedFor(const Scene &scene, const glm::vec3 &boundsMin, const glm::vec3 &boundsMax) {
    float viewDistance = float(glm::length(scene.camera.look - scene.camera.eye));
    float size = scene.finitePrimitiveCount() > 0 ? glm::length(boundsMax - boundsMin) : 0.0f;
    return 0.25f * std::max({size, 2.0f * viewDistance, 1e-3f});
}

bool sameCamera(const Camera &a, const Camera &b) {
    return a.eye == b.eye && a.look == b.look && a.up == b.up && a.fovDegrees == b.fovDegrees &&
           a.orthoHeight == b.orthoHeight;
}

} // namespace prism
