#pragma once
// Ray/primitive tests of the CPU reference: the shader's (shaders/intersect.glsl) in double.
// Every test reports a hit only for 0 < t < tMax; rays have unit directions.
#include <glm/glm.hpp>

#include "reference/camera_model.h"
#include "scene/scene.h"

namespace prism::reference {

// A plane as n . x = offset with n unit length (the shader's normalOffset).
struct PlaneEquation {
    glm::dvec3 normal;
    double offset;
};

PlaneEquation planeEquation(const Plane &plane);

// Numerically stable form (Haines et al., Ray Tracing Gems ch. 7), as intersectSphere.
bool intersectSphere(const Ray &ray, glm::dvec3 center, double radius, double tMax, double &t);

bool intersectPlane(const Ray &ray, const PlaneEquation &plane, double tMax, double &t);

// Per-ray constants of the watertight triangle test (Woop, Benthin & Wald 2013): the axis of
// largest |dir| becomes z, the other two are sheared so the ray runs along +z.
struct WatertightRay {
    int kx, ky, kz;
    glm::dvec3 shear; // Sx, Sy, Sz
};

WatertightRay makeWatertightRay(glm::dvec3 dir);

// Watertight ray/triangle test; b12 are the barycentrics of p1 and p2. A ray through an edge
// shared by two triangles hits at least one of them: the shared edge function is computed from
// the same products in both, so its sign agrees.
bool intersectTriangle(const Ray &ray, const WatertightRay &wray, glm::dvec3 p0, glm::dvec3 p1,
                       glm::dvec3 p2, double tMax, double &t, glm::dvec2 &b12);

} // namespace prism::reference
