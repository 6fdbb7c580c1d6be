#pragma once
// The scene's finite primitives as the grid sees them: by grid id (scene/primitive_ids.h), each
// with its bounds and an exact test against a box. The one place in the grid that knows the
// kinds, so a builder walks ids and never a kind's own array.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "accel/bounds.h"
#include "scene/primitive_ids.h"
#include "scene/scene.h"

namespace prism {

class FinitePrimitives {
public:
    explicit FinitePrimitives(const Scene &scene);

    uint32_t count() const { return ids_.count(); }
    Aabb bounds(uint32_t id) const;
    // Closed sets: touching counts as overlap. An instance counts as its box (in world space,
    // the bounds of its prototype's box placed), which holds every triangle of the placement.
    bool overlapsBox(uint32_t id, const glm::dvec3 &boxMin, const glm::dvec3 &boxMax) const;
    // Whether the primitive's surface may meet the box: as overlapsBox, less a box wholly inside
    // a sphere (a ray reaches such a box only through the surface in front of it).
    bool surfaceMayMeetBox(uint32_t id, const glm::dvec3 &boxMin, const glm::dvec3 &boxMax) const;

private:
    const Scene &scene_;
    PrimitiveIds ids_;
    std::vector<Aabb> instanceBounds_; // by instance
};

// The bounds of a prototype's triangles in its own space.
Aabb prototypeBounds(const MeshPrototype &prototype);
// The world box of a placed box: the bounds of its eight corners placed.
Aabb placedBounds(const Instance &instance, const Aabb &objectBounds);

} // namespace prism
