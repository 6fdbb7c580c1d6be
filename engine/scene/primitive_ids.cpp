#include "scene/primitive_ids.h"

#include "core/error.h"

namespace prism {

PrimitiveIds::PrimitiveIds(const Scene &scene) {
    static_assert(gpu::kFiniteKindCount <= 4, "the ends travel in one uvec4");
    uint64_t counts[gpu::kFiniteKindCount] = {};
    counts[gpu::kKindSphere] = scene.spheres.size();
    counts[gpu::kKindTriangle] = scene.triangles.size();
    counts[gpu::kKindInstance] = scene.instances.size();
    uint64_t total = 0;
    for (uint32_t kind = 0; kind < 4; ++kind) {
        if (kind < gpu::kFiniteKindCount)
            total += counts[kind];
        if (total >= (uint64_t(1) << 32))
            throw Error("scene has more than 2^32 spheres, triangles and instances");
        end[int(kind)] = uint32_t(total);
    }
}

PrimitiveIds::Decoded PrimitiveIds::decode(uint32_t id) const {
    uint32_t kind = 0;
    while (kind + 1 < gpu::kFiniteKindCount && id >= end[int(kind)])
        ++kind;
    return {kind, id - first(kind)};
}

} // namespace prism
