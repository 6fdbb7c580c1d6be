#include "scene/camera_animation.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/key_interpolation.h"
#include "scene/number_parser.h"

namespace prism {
namespace {

// The keys as one list: the camera line at frame 1, then the `key` lines.
std::vector<CameraKey> allKeys(const Scene &scene) {
    std::vector<CameraKey> keys;
    keys.reserve(scene.cameraAnimation.keys.size() + 1);
    keys.push_back(CameraKey{1.0, scene.camera, 0});
    keys.insert(keys.end(), scene.cameraAnimation.keys.begin(), scene.cameraAnimation.keys.end());
    return keys;
}

Camera keyedCamera(const Scene &scene, double frame) {
    std::vector<CameraKey> keys = allKeys(scene);
    if (frame <= keys.front().frame)
        return keys.front().camera;
    if (frame >= keys.back().frame)
        return keys.back().camera;
    KeySegment segment = keySegment(keys, frame);
    size_t i = segment.i;
    if (segment.u == 0.0)
        return keys[i].camera;
    KeyInterpolation mode = scene.keyInterpolation;
    Camera c = keys[i].camera;
    c.eye = blendKeys<glm::dvec3>(keys, segment, mode, [](const CameraKey &k) { return k.camera.eye; });
    c.look = blendKeys<glm::dvec3>(keys, segment, mode, [](const CameraKey &k) { return k.camera.look; });
    c.up = glm::vec3(blendKeys<glm::dvec3>(
        keys, segment, mode, [](const CameraKey &k) { return glm::dvec3(k.camera.up); }));
    if (c.isOrtho())
        c.orthoHeight = float(blendKeys<double>(
            keys, segment, mode, [](const CameraKey &k) { return double(k.camera.orthoHeight); }));
    else
        c.fovDegrees = float(blendKeys<double>(
            keys, segment, mode, [](const CameraKey &k) { return double(k.camera.fovDegrees); }));
    // A spline can overshoot where a straight line would not: into eye = look, a degenerate
    // up, a field of view out of (0, 180) or a parallel camera of no height.
    glm::dvec3 forward = c.look - c.eye;
    bool seesNothing = !(glm::length(forward) > 0.0) ||
                       glm::length(glm::cross(glm::normalize(forward), glm::dvec3(c.up))) <=
                           1e-6 * glm::length(glm::dvec3(c.up)) ||
                       (c.isOrtho() ? !(c.orthoHeight > 0.0f)
                                    : !(c.fovDegrees > 0.0f && c.fovDegrees < 180.0f));
    if (c.isOrtho() == keys[i].camera.isOrtho() && !seesNothing)
        return c;
    auto lineOf = [](const CameraKey &k) {
        return k.line == 0 ? std::string("the camera line") : "line " + std::to_string(k.line);
    };
    throw Error("frame " + formatNumber(frame) + ": the camera between the keys of " +
                lineOf(keys[i]) + " and " + lineOf(keys[i + 1]) +
                " has no view (its eye meets its look, its up lies along the view, or its field "
                "of view leaves (0, 180)); move the keys apart or use 'interpolate linear'");
}

// Rodrigues' rotation of v about the unit axis k by `radians`.
glm::dvec3 rotated(const glm::dvec3 &v, const glm::dvec3 &k, double radians) {
    double c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0 - c));
}

Camera turntableCamera(const Scene &scene, const Turntable &t, double frame) {
    // Frame 1 and every whole turn after it are the camera line itself, to the bit: a loop of
    // FRAMES frames closes without a seam.
    double turns = t.degrees / 360.0 * ((frame - 1.0) / t.frames);
    double part = turns - std::floor(turns);
    if (part == 0.0)
        return scene.camera;
    double radians = part * 2.0 * 3.14159265358979323846;
    Camera c = scene.camera;
    c.eye = t.center + rotated(scene.camera.eye - t.center, t.axis, radians);
    c.look = t.center + rotated(scene.camera.look - t.center, t.axis, radians);
    c.up = glm::vec3(rotated(glm::dvec3(scene.camera.up), t.axis, radians));
    return c;
}

} // namespace

Camera cameraAt(const Scene &scene, double frame) {
    const CameraAnimation &a = scene.cameraAnimation;
    if (a.turntable)
        return turntableCamera(scene, *a.turntable, frame);
    if (!a.keys.empty())
        return keyedCamera(scene, frame);
    return scene.camera;
}

} // namespace prism
