#include "render/tracer_features.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "render/loop_bound.h"
#include "scene/primitive_ids.h"
#include "shared/trace_interface.h"

namespace prism {
namespace {

// lavapipe silently ends an invocation's loops after 65,535 iterations in total; the tracer
// stops a little earlier (its own count is conservative) and reports the pixel instead.
constexpr uint32_t kLavapipeLoopBudget = 60000;

} // namespace

TracerFeatures featuresOf(const Scene &scene) {
    TracerFeatures f;
    PrimitiveIds ids(scene);
    for (uint32_t kind = 0; kind < gpu::kFiniteKindCount; ++kind)
        if (ids.end[int(kind)] > ids.first(kind))
            f.kinds |= 1u << kind;
    if (!scene.planes.empty())
        f.kinds |= 1u << gpu::kKindPlane;
    auto used = [&](auto predicate) {
        return std::any_of(scene.materials.begin(), scene.materials.end(), predicate);
    };
    f.reflection = used([](const Material &m) { return m.reflect > 0.0f; });
    f.transmission = used([](const Material &m) { return m.transmit > 0.0f; });
    f.textures = used([](const Material &m) { return m.texture != kNoTexture; });
    f.areaLights = std::any_of(scene.lights.begin(), scene.lights.end(),
                               [](const Light &l) { return l.radius > 0.0f; });
    f.vertexNormals = std::any_of(scene.triangles.begin(), scene.triangles.end(),
                                  [](const Triangle &t) { return t.hasNormals; });
    return f;
}

TracerFeatures chooseFeatures(const Scene &scene, const Grid &grid, const TracerOptions &options,
                              bool deviceCutsLongLoops) {
    if (options.maxDepth < 1 || options.maxDepth > 64)
        throw Error("ray depth " + std::to_string(options.maxDepth) + " is outside 1..64");
    TracerFeatures f = featuresOf(scene);
    f.maxDepth = options.maxDepth;
    f.texelBuffers = options.texelBuffers;
    f.writeAov = options.writeAov;
    f.adaptiveGrid = grid.adaptive();
    f.shadows = options.shadows;
    f.reflection = f.reflection && options.reflection;
    f.transmission = f.transmission && options.transmission;
    if (options.loopBudget >= 0)
        f.loopBudget = uint32_t(options.loopBudget);
    else if (deviceCutsLongLoops)
        f.loopBudget = invocationIterationBound(scene, grid, f) < kLavapipeLoopBudget
                           ? 0u // provably within lavapipe's limit: no counting needed
                           : kLavapipeLoopBudget;
    else
        f.loopBudget = 0u;
    return f;
}

std::vector<vk::SpecializationConstant> TracerFeatures::specialization() const {
    uint32_t stackSize = std::max(1u, 2u * maxDepth - 1u); // see pushRay in trace.comp
    return {{gpu::kSpecKinds, kinds},
            {gpu::kSpecHasReflection, reflection},
            {gpu::kSpecHasTransmission, transmission},
            {gpu::kSpecHasTextures, textures},
            {gpu::kSpecHasAreaLights, areaLights},
            {gpu::kSpecHasVertexNormals, vertexNormals},
            {gpu::kSpecHasShadows, shadows},
            {gpu::kSpecWriteAov, writeAov},
            {gpu::kSpecLoopBudget, loopBudget},
            {gpu::kSpecStackSize, stackSize},
            {gpu::kSpecTexelBuffers, texelBuffers},
            {gpu::kSpecAdaptiveGrid, adaptiveGrid}};
}

} // namespace prism
