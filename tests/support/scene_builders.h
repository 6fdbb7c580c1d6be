#pragma once
// Building small scenes in code: materials, triangles and closed meshes added to a Scene, each
// returning or using material indices the way the scene parser assigns them.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::test {

// Material 0 is the default, as in a parsed scene, so primitives may name it.
inline Scene sceneWithDefaultMaterial() {
    Scene scene;
    scene.materials.push_back(Material{"default"});
    return scene;
}

// Appends `m` and returns its index.
inline uint32_t addMaterial(Scene &scene, Material m) {
    scene.materials.push_back(m);
    return uint32_t(scene.materials.size() - 1);
}

// A coloured material with a visible highlight (specular 0.4), optionally a mirror or glass.
inline uint32_t addMaterial(Scene &scene, const std::string &name, glm::vec3 color,
                            float reflect = 0.0f, float transmit = 0.0f) {
    Material m;
    m.name = name;
    m.color = color;
    m.specular = 0.4f;
    m.reflect = reflect;
    m.transmit = transmit;
    return addMaterial(scene, m);
}

// A material that only passes light on (no ambient, diffuse or specular of its own).
inline Material opticalMaterial(const std::string &name, float reflect, float transmit,
                                float ior = 1.5f) {
    Material m;
    m.name = name;
    m.color = glm::vec3(1.0f);
    m.ambient = 0.0f;
    m.diffuse = 0.0f;
    m.specular = 0.0f;
    m.reflect = reflect;
    m.transmit = transmit;
    m.ior = ior;
    return m;
}

inline void addTriangle(Scene &scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material) {
    Triangle t;
    t.p[0] = a;
    t.p[1] = b;
    t.p[2] = c;
    t.material = material;
    scene.triangles.push_back(t);
}

// Regular octahedron with vertices at +-radius on each axis: 8 faces, outward winding.
inline void addOctahedron(Scene &scene, glm::vec3 center, float radius, uint32_t material) {
    glm::vec3 px = center + glm::vec3(radius, 0, 0), nx = center - glm::vec3(radius, 0, 0);
    glm::vec3 py = center + glm::vec3(0, radius, 0), ny = center - glm::vec3(0, radius, 0);
    glm::vec3 pz = center + glm::vec3(0, 0, radius), nz = center - glm::vec3(0, 0, radius);
    addTriangle(scene, px, py, pz, material);
    addTriangle(scene, py, nx, pz, material);
    addTriangle(scene, nx, ny, pz, material);
    addTriangle(scene, ny, px, pz, material);
    addTriangle(scene, py, px, nz, material);
    addTriangle(scene, nx, py, nz, material);
    addTriangle(scene, ny, nx, nz, material);
    addTriangle(scene, px, ny, nz, material);
}

// Adds a regular octahedron shaded as a sphere: vertex normals point away from the centre
// (0.58 from the faces' own), and texture coordinates run around it.
inline void addSmoothOctahedron(Scene &scene, glm::vec3 center, float radius, uint32_t material) {
    size_t first = scene.triangles.size();
    addOctahedron(scene, center, radius, material);
    for (size_t i = first; i < scene.triangles.size(); ++i) {
        TriangleShading &t = shadingFor(scene.triangles[i], scene.triangleShading);
        t.hasNormals = t.hasUVs = true;
        for (int c = 0; c < 3; ++c) {
            glm::vec3 n = glm::normalize(glm::vec3(scene.triangles[i].p[c]) - center);
            t.n[c] = n;
            t.uv[c] = {0.5f + 0.4f * n.x + 0.1f * n.z, 0.5f + 0.4f * n.y - 0.1f * n.z};
        }
    }
}

} // namespace prism::test
