#include "render/tracer_features.h"

#include <algorithm>

namespace prism {

TracerFeatures featuresOf(const Scene &scene) {
    TracerFeatures f;
    f.spheres = !scene.spheres.empty();
    f.planes = !scene.planes.empty();
    f.triangles = !scene.triangles.empty();
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

std::vector<uint32_t> TracerFeatures::specialization() const {
    uint32_t stackSize = std::max(1u, 2u * maxDepth - 1u); // see pushRay in trace.comp
    return {spheres,       planes,  triangles, reflection, transmission, textures,    areaLights,
            vertexNormals, shadows, writeAov,  loopBudget, stackSize,    texelBuffers};
}

} // namespace prism
