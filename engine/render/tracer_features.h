#pragma once
// Which tracer features a scene needs; each becomes a specialization constant so a scene pays
// only for what it uses (no refraction code when nothing transmits, ...).
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace prism {

struct TracerFeatures {
    bool spheres = false;
    bool planes = false;
    bool triangles = false;
    bool reflection = false;
    bool transmission = false;
    bool textures = false;
    bool areaLights = false;
    bool vertexNormals = false;
    bool shadows = true;
    bool writeAov = false;
    uint32_t loopBudget = 0; // 0: unlimited
    uint32_t maxDepth = 5;
    bool texelBuffers = false; // hot arrays through uniform texel buffers

    // Constant ids 0.. in the order of shaders/bindings.glsl.
    std::vector<uint32_t> specialization() const;
};

TracerFeatures featuresOf(const Scene &scene);

} // namespace prism
