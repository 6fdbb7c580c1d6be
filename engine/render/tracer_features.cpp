#include "render/tracer_features.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "core/error.h"
#include "render/scene_packing.h"
#include "scene/primitive_ids.h"
#include "shared/trace_interface.h"

namespace prism {
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
    f.surfaceMaps = used([](const Material &m) { return m.hasSurfaceMaps(); });
    f.environment = scene.environment.texture != kNoTexture;
    f.areaLights = std::any_of(scene.lights.begin(), scene.lights.end(),
                               [](const Light &l) { return l.radius > 0.0f; });
    // Every record is some triangle's (nothing makes one without a triangle pointing to it).
    auto anyNormals = [](const std::vector<TriangleShading> &shading) {
        return std::any_of(shading.begin(), shading.end(),
                           [](const TriangleShading &s) { return s.hasNormals; });
    };
    f.vertexNormals = anyNormals(scene.triangleShading);
    for (const MeshPrototype &m : scene.prototypes)
        f.vertexNormals = f.vertexNormals || anyNormals(m.shading);
    return f;
}

TracerFeatures chooseFeatures(const Scene &scene, const Grid &grid, const TracerOptions &options,
                              uint64_t maxTexelElements) {
    if (options.maxDepth < 1 || options.maxDepth > 64)
        throw Error("ray depth " + std::to_string(options.maxDepth) + " is outside 1..64");
    TracerFeatures f = featuresOf(scene);
    f.maxDepth = options.maxDepth;
    f.texelBuffers = options.texelBuffers;
    f.writeAov = options.writeAov;
    f.adaptiveGrid = grid.adaptive();
    if (options.profile > 2)
        throw Error("profile level " + std::to_string(options.profile) + " is outside 0..2");
    f.profile = options.profile;
    f.resumable = options.resumable;
    f.resumeLaneBudget = options.resumeLaneBudget;
    f.shadows = options.shadows;
    // At depth 1 no ray is ever reflected or refracted: compile that code out too (lavapipe
    // would otherwise run it, masked, for every hit).
    f.reflection = f.reflection && options.reflection && options.maxDepth > 1;
    f.transmission = f.transmission && options.transmission && options.maxDepth > 1;
    if (!std::isfinite(options.fixedRayOffset) || options.fixedRayOffset < 0.0f)
        throw Error("fixed ray offset " + std::to_string(options.fixedRayOffset) +
                    " is not a finite number >= 0 (0: Prism's relative offset)");
    f.fixedRayOffset = options.fixedRayOffset;
    f.mollerTrumbore = options.mollerTrumbore;
    uint32_t finiteKinds = f.kinds & ~(1u << gpu::kKindPlane);
    uint64_t entries = grid.cellPrimitives.size();
    bool cells = options.cellPrimitives && f.texelBuffers && !grid.lean;
    // On an adaptive grid the rows hold the cell records, which the voxel map's leaves name by
    // 28 bits (render/scene_packing.h).
    uint64_t rows = cellTriangleRows(grid, true);
    f.cellTriangles = cells && finiteKinds == (1u << gpu::kKindTriangle) &&
                      rows <= maxTexelElements && (!grid.adaptive() || rows <= kMaxAdaptiveIndex);
    f.cellSpheres = cells && finiteKinds == (1u << gpu::kKindSphere) && entries <= maxTexelElements;
    return f;
}

TracerFeatures TracerFeatures::backgroundOnly() const {
    TracerFeatures f = *this;
    f.kinds = 0;
    f.reflection = f.transmission = f.textures = f.areaLights = f.vertexNormals = false;
    f.surfaceMaps = f.shadows = f.adaptiveGrid = f.cellTriangles = f.cellSpheres = false;
    return f;
}

TracerFeatures TracerFeatures::planesOnly(bool reflections) const {
    TracerFeatures f = *this;
    f.kinds &= 1u << gpu::kKindPlane;
    f.reflection = f.reflection && reflections;
    f.transmission = f.vertexNormals = false;
    f.adaptiveGrid = f.cellTriangles = f.cellSpheres = false;
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
            {gpu::kSpecHasEnvironment, environment},
            {gpu::kSpecHasShadows, shadows},
            {gpu::kSpecWriteAov, writeAov},
            {gpu::kSpecStackSize, stackSize},
            {gpu::kSpecTexelBuffers, texelBuffers},
            {gpu::kSpecAdaptiveGrid, adaptiveGrid},
            {gpu::kSpecHasSurfaceMaps, surfaceMaps},
            {gpu::kSpecCellTriangles, cellTriangles},
            {gpu::kSpecCellSpheres, cellSpheres},
            {gpu::kSpecProfileWalkDetail, profile >= 2},
            {gpu::kSpecResumable, resumable},
            {gpu::kSpecResumeLaneBudget,
             resumeLaneBudget == 0 ? gpu::kResumeLaneBudget : resumeLaneBudget},
            {gpu::kSpecFixedRayOffset, std::bit_cast<uint32_t>(fixedRayOffset)},
            {gpu::kSpecTriangleTest,
             mollerTrumbore ? gpu::kTriangleTestMollerTrumbore : gpu::kTriangleTestWatertight}};
}

} // namespace prism
