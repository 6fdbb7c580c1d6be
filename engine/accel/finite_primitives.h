#pragma once
// The scene's finite primitives as the grid sees them: by grid id (scene/primitive_ids.h), each
// with its bounds and an exact test against a box. The one place in the grid that knows the
// kinds, so a builder walks ids and never a kind's own array.
#include <cstdint>

#include <glm/glm.hpp>

#include "accel/bounds.h"
#include "scene/primitive_ids.h"
#include "scene/scene.h"

namespace prism {

class FinitePrimitives {
public:
    explicit FinitePrimitives(const Scene &scene) : scene_(scene), ids_(scene) {}

    uint32_t count() const { return ids_.count(); }
    Aabb bounds(uint32_t id) const;
    // Closed sets: touching counts as overlap.
    bool overlapsBox(uint32_t id, const glm::dvec3 &boxMin, const glm::dvec3 &boxMax) const;

private:
    const Scene &scene_;
    PrimitiveIds ids_;
};

} // namespace prism
