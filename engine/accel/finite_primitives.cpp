#include "accel/finite_primitives.h"

#include "accel/overlap_tests.h"

namespace prism {
namespace {

Aabb sphereBounds(const Sphere &s) {
    glm::dvec3 c = s.center, r(double(s.radius));
    return {c - r, c + r};
}

Aabb triangleBounds(const Triangle &t) {
    Aabb b;
    for (const glm::dvec3 &p : t.p)
        b.grow(p);
    return b;
}

} // namespace

Aabb FinitePrimitives::bounds(uint32_t id) const {
    PrimitiveIds::Decoded p = ids_.decode(id);
    if (p.kind == gpu::kKindSphere)
        return sphereBounds(scene_.spheres[p.index]);
    return triangleBounds(scene_.triangles[p.index]);
}

bool FinitePrimitives::overlapsBox(uint32_t id, const glm::dvec3 &boxMin,
                                   const glm::dvec3 &boxMax) const {
    PrimitiveIds::Decoded p = ids_.decode(id);
    if (p.kind == gpu::kKindSphere) {
        const Sphere &s = scene_.spheres[p.index];
        return sphereOverlapsBox(s.center, double(s.radius), boxMin, boxMax);
    }
    const Triangle &t = scene_.triangles[p.index];
    return triangleOverlapsBox(t.p[0], t.p[1], t.p[2], boxMin, boxMax);
}

} // namespace prism
