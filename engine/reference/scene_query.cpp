#include "reference/scene_query.h"

#include "reference/intersect_reference.h"

namespace prism::reference {
namespace {

glm::dvec3 vertex(const Triangle &tri, int i) {
    return glm::dvec3(tri.p[i]);
}

} // namespace

bool traceClosest(const Scene &scene, const Ray &ray, double tMax, Hit &hit) {
    hit = Hit{};
    hit.t = tMax;
    double t = 0.0;
    // Each test is bounded by the best hit so far, so only strictly nearer hits replace it (the
    // shader does the same, planes first).
    for (uint32_t i = 0; i < scene.planes.size(); ++i) {
        if (intersectPlane(ray, planeEquation(scene.planes[i]), hit.t, t)) {
            hit.t = t;
            hit.kind = HitKind::Plane;
            hit.index = i;
        }
    }
    for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere &s = scene.spheres[i];
        if (intersectSphere(ray, glm::dvec3(s.center), double(s.radius), hit.t, t)) {
            hit.t = t;
            hit.kind = HitKind::Sphere;
            hit.index = i;
        }
    }
    if (!scene.triangles.empty()) {
        WatertightRay wray = makeWatertightRay(ray.dir);
        glm::dvec2 b12;
        for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
            const Triangle &tri = scene.triangles[i];
            if (intersectTriangle(ray, wray, vertex(tri, 0), vertex(tri, 1), vertex(tri, 2), hit.t,
                                  t, b12)) {
                hit.t = t;
                hit.kind = HitKind::Triangle;
                hit.index = i;
                hit.b12 = b12;
            }
        }
    }
    return hit.kind != HitKind::None;
}

bool traceOccluded(const Scene &scene, const Ray &ray, double tMax) {
    double t = 0.0;
    for (const Plane &p : scene.planes)
        if (intersectPlane(ray, planeEquation(p), tMax, t))
            return true;
    for (const Sphere &s : scene.spheres)
        if (intersectSphere(ray, glm::dvec3(s.center), double(s.radius), tMax, t))
            return true;
    if (!scene.triangles.empty()) {
        WatertightRay wray = makeWatertightRay(ray.dir);
        glm::dvec2 b12;
        for (const Triangle &tri : scene.triangles)
            if (intersectTriangle(ray, wray, vertex(tri, 0), vertex(tri, 1), vertex(tri, 2), tMax,
                                  t, b12))
                return true;
    }
    return false;
}

} // namespace prism::reference
