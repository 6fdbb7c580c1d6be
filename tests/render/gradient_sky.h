#pragma once
// A lat-long sky whose red channel is its own v coordinate (v = 0.5 + asin(y) / pi, 0 at the
// bottom, as docs/scene-format.md defines the environment's rows), constant along each row.
// Bilinear filtering of a function linear in v is exact, so a ray that reaches the sky reads back
// the elevation of its direction: tests of the environment's vertical axis and of refracted
// directions compare that against hand-computed angles, not against the other renderer.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::test {

constexpr int kGradientSkyRows = 16;
constexpr double kPi = 3.14159265358979323846;

// The sky's value for direction `dir`: v as the shader computes it, held half a texel from the
// poles as it is (beyond the first and last rows' centres the rows do not change).
inline double gradientSkyRed(glm::dvec3 dir) {
    double v = 0.5 + std::asin(std::clamp(glm::normalize(dir).y, -1.0, 1.0)) / kPi;
    double halfTexel = 0.5 / kGradientSkyRows;
    return std::clamp(v, halfTexel, 1.0 - halfTexel);
}

// Adds the sky to `scene` as its environment, at intensity 1 and no rotation. Green is 1 - v so
// that an upside-down lookup differs in two channels; blue is constant.
inline void addGradientSky(Scene &scene) {
    Texture sky;
    sky.path = "gradient-sky";
    sky.width = 4;
    sky.height = kGradientSkyRows;
    for (int row = 0; row < kGradientSkyRows; ++row) { // stored top row first
        float v = (float(kGradientSkyRows - 1 - row) + 0.5f) / float(kGradientSkyRows);
        for (int c = 0; c < sky.width; ++c)
            sky.texels.push_back({v, 1.0f - v, 0.25f, 1.0f});
    }
    scene.textures.push_back(sky);
    scene.environment.texture = int32_t(scene.textures.size() - 1);
    scene.environment.intensity = 1.0f;
    scene.environment.rotateDegrees = 0.0f;
    scene.background = {1.0f, 0.0f, 1.0f}; // must not be seen
}

// A camera at the origin whose centre pixel (of an odd-sized image) looks exactly along `dir`.
inline Camera cameraAlong(glm::dvec3 dir, glm::vec3 up = {0.0f, 1.0f, 0.0f}) {
    Camera camera;
    camera.eye = glm::dvec3(0.0);
    camera.look = dir;
    camera.up = up;
    return camera;
}

} // namespace prism::test
