#pragma once
// The grid's id space over a scene's finite primitives: one contiguous range per kind, kinds in
// the order of shaders/shared/primitive_kinds.h (spheres, then triangles). The grid stores these
// ids, the tracer decodes them with the same ranges (GpuSceneHeader::idEnd).
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "shared/primitive_kinds.h"

namespace prism {

struct PrimitiveIds {
    glm::uvec4 end{0u}; // [kind]: one past the kind's last id; unused kinds repeat the total

    // Throws prism::Error when the scene has 2^32 or more finite primitives.
    explicit PrimitiveIds(const Scene &scene);

    uint32_t first(uint32_t kind) const { return gpu::primitiveIdFirst(end, kind); }
    uint32_t count() const { return end[gpu::kFiniteKindCount - 1]; }

    struct Decoded {
        uint32_t kind;
        uint32_t index; // within the kind's array
    };
    Decoded decode(uint32_t id) const;
};

} // namespace prism
