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

Aabb prototypeBounds(const MeshPrototype &prototype) {
    Aabb b;
    for (const Triangle &t : prototype.triangles)
        b.grow(triangleBounds(t));
    return b;
}

Aabb placedBounds(const Instance &instance, const Aabb &objectBounds) {
    Aabb b;
    if (objectBounds.empty())
        return b;
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 p((corner & 1) ? objectBounds.max.x : objectBounds.min.x,
                     (corner & 2) ? objectBounds.max.y : objectBounds.min.y,
                     (corner & 4) ? objectBounds.max.z : objectBounds.min.z);
        b.grow(instance.toWorld(p));
    }
    return b;
}

FinitePrimitives::FinitePrimitives(const Scene &scene) : scene_(scene), ids_(scene) {
    std::vector<Aabb> objectBounds;
    for (const MeshPrototype &prototype : scene.prototypes)
        objectBounds.push_back(prototypeBounds(prototype));
    for (const Instance &instance : scene.instances)
        instanceBounds_.push_back(placedBounds(instance, objectBounds.at(instance.prototype)));
}

Aabb FinitePrimitives::bounds(uint32_t id) const {
    PrimitiveIds::Decoded p = ids_.decode(id);
    if (p.kind == gpu::kKindSphere)
        return sphereBounds(scene_.spheres[p.index]);
    if (p.kind == gpu::kKindInstance)
        return instanceBounds_[p.index];
    return triangleBounds(scene_.triangles[p.index]);
}

bool FinitePrimitives::overlapsBox(uint32_t id, const glm::dvec3 &boxMin,
                                   const glm::dvec3 &boxMax) const {
    PrimitiveIds::Decoded p = ids_.decode(id);
    if (p.kind == gpu::kKindSphere) {
        const Sphere &s = scene_.spheres[p.index];
        return sphereOverlapsBox(s.center, double(s.radius), boxMin, boxMax);
    }
    if (p.kind == gpu::kKindInstance) {
        const Aabb &b = instanceBounds_[p.index];
        return glm::all(glm::lessThanEqual(b.min, boxMax)) &&
               glm::all(glm::lessThanEqual(boxMin, b.max));
    }
    const Triangle &t = scene_.triangles[p.index];
    return triangleOverlapsBox(t.p[0], t.p[1], t.p[2], boxMin, boxMax);
}

bool FinitePrimitives::surfaceMayMeetBox(uint32_t id, const glm::dvec3 &boxMin,
                                         const glm::dvec3 &boxMax) const {
    if (!overlapsBox(id, boxMin, boxMax))
        return false;
    PrimitiveIds::Decoded p = ids_.decode(id);
    if (p.kind != gpu::kKindSphere)
        return true;
    // Inside when the farthest corner is, with a margin far above the rounding of this sum.
    const Sphere &s = scene_.spheres[p.index];
    glm::dvec3 c = s.center;
    glm::dvec3 far = glm::max(glm::abs(boxMin - c), glm::abs(boxMax - c));
    double r = double(s.radius);
    return glm::dot(far, far) >= r * r * (1.0 - 1e-6);
}

} // namespace prism
