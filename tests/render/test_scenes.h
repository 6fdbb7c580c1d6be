#pragma once
// Small scenes built in code for the stability tests.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::test {

inline uint32_t addMaterial(Scene &scene, const std::string &name, glm::vec3 color,
                            float reflect = 0.0f, float transmit = 0.0f) {
    Material m;
    m.name = name;
    m.color = color;
    m.specular = 0.4f;
    m.reflect = reflect;
    m.transmit = transmit;
    scene.materials.push_back(m);
    return uint32_t(scene.materials.size() - 1);
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

// A floor, a mirror sphere, a glass sphere, a diffuse sphere resting on the floor and an
// octahedron: contact shadows, reflections and refraction all in view. Coordinates are
// multiples of 1/16, so moving the scene by 1e4 (float spacing 2^-10 there) is exact and any
// difference comes from the tracer, not from moved geometry.
inline Scene stabilityScene() {
    Scene scene;
    scene.materials.push_back(Material{"default"});
    uint32_t floor = addMaterial(scene, "floor", {0.7f, 0.7f, 0.7f}, 0.2f);
    uint32_t mirror = addMaterial(scene, "mirror", {0.9f, 0.9f, 0.9f}, 0.8f);
    uint32_t glass = addMaterial(scene, "glass", {1.0f, 1.0f, 1.0f}, 0.0f, 0.9f);
    uint32_t red = addMaterial(scene, "red", {0.9f, 0.2f, 0.1f});
    uint32_t blue = addMaterial(scene, "blue", {0.2f, 0.3f, 0.9f});
    scene.camera.eye = {0.0f, 2.5f, 7.0f};
    scene.camera.look = {0.0f, 0.8125f, 0.0f};
    scene.camera.fovDegrees = 50.0f;
    scene.background = {0.1f, 0.1f, 0.15f};
    scene.lights.push_back(Light{{4.0f, 6.0f, 5.0f}, {1.0f, 1.0f, 1.0f}, 0.0f});
    scene.planes.push_back(Plane{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, floor});
    scene.spheres.push_back(Sphere{{-1.625f, 1.0f, 0.0f}, 1.0f, mirror});
    scene.spheres.push_back(Sphere{{0.875f, 0.6875f, 1.1875f}, 0.6875f, glass});
    scene.spheres.push_back(Sphere{{1.8125f, 0.5f, -1.0f}, 0.5f, red});
    addOctahedron(scene, {0.1875f, 0.625f, -1.625f}, 0.625f, blue);
    return scene;
}

// Every position scaled by `scale` then moved by `offset`; directions and colours unchanged.
inline Scene transformed(Scene scene, float scale, glm::vec3 offset) {
    auto move = [&](glm::vec3 p) { return p * scale + offset; };
    scene.camera.eye = move(scene.camera.eye);
    scene.camera.look = move(scene.camera.look);
    for (Light &l : scene.lights) {
        l.position = move(l.position);
        l.radius *= scale;
    }
    for (Sphere &s : scene.spheres) {
        s.center = move(s.center);
        s.radius *= scale;
    }
    for (Plane &p : scene.planes)
        p.point = move(p.point);
    for (Triangle &t : scene.triangles)
        for (glm::vec3 &p : t.p)
            p = move(p);
    return scene;
}

} // namespace prism::test
