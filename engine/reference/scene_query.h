#pragma once
// What a ray hits in a scene, by brute force over every primitive (no grid): the reference
// answer the shader's grid traversal (shaders/traverse.glsl) must reproduce.
#include <cstdint>

#include <glm/glm.hpp>

#include "reference/camera_model.h"
#include "scene/scene.h"

namespace prism::reference {

enum class HitKind { None, Sphere, Plane, Triangle };

struct Hit {
    double t = 0.0;
    HitKind kind = HitKind::None;
    uint32_t index = 0;       // into scene.spheres, scene.planes or scene.triangles
    glm::dvec2 b12{0.0, 0.0}; // triangle barycentrics of p1 and p2
};

// Closest hit with 0 < t < tMax over all planes, spheres and triangles.
bool traceClosest(const Scene &scene, const Ray &ray, double tMax, Hit &hit);

// True when any primitive lies on the open segment 0 < t < tMax (shadow rays).
bool traceOccluded(const Scene &scene, const Ray &ray, double tMax);

} // namespace prism::reference
