#pragma once
// Small scenes built in code for the CPU reference's tests.
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::test {

inline Scene sceneWithDefaultMaterial() {
    Scene scene;
    scene.materials.push_back(Material{"default"});
    return scene;
}

inline uint32_t addMaterial(Scene &scene, Material m) {
    scene.materials.push_back(m);
    return uint32_t(scene.materials.size() - 1);
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

// Floor, mirror sphere, glass sphere, diffuse sphere and two triangles under one light: every
// code path of the tracer in view.
inline Scene mixedScene(float lightRadius = 0.0f) {
    Scene scene = sceneWithDefaultMaterial();
    Material floor;
    floor.name = "floor";
    floor.color = {0.7f, 0.7f, 0.6f};
    floor.reflect = 0.2f;
    uint32_t floorId = addMaterial(scene, floor);
    Material mirror = opticalMaterial("mirror", 0.8f, 0.0f);
    mirror.ambient = 0.05f;
    uint32_t mirrorId = addMaterial(scene, mirror);
    Material glass = opticalMaterial("glass", 0.0f, 0.9f);
    glass.specular = 0.8f;
    glass.shininess = 100.0f;
    uint32_t glassId = addMaterial(scene, glass);
    Material red;
    red.name = "red";
    red.color = {0.9f, 0.2f, 0.1f};
    red.specular = 0.4f;
    uint32_t redId = addMaterial(scene, red);
    scene.camera.eye = {0.0f, 2.5f, 7.0f};
    scene.camera.look = {0.0f, 0.8f, 0.0f};
    scene.camera.fovDegrees = 50.0f;
    scene.background = {0.1f, 0.1f, 0.15f};
    scene.lights.push_back(Light{{4.0f, 6.0f, 5.0f}, {1.0f, 1.0f, 1.0f}, lightRadius});
    scene.planes.push_back(Plane{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, floorId});
    scene.spheres.push_back(Sphere{{-1.6f, 1.0f, 0.0f}, 1.0f, mirrorId});
    scene.spheres.push_back(Sphere{{0.9f, 0.7f, 1.2f}, 0.7f, glassId});
    scene.spheres.push_back(Sphere{{1.8f, 0.5f, -1.0f}, 0.5f, redId});
    addTriangle(scene, {-0.5f, 0.0f, -2.0f}, {0.7f, 0.0f, -2.2f}, {0.1f, 1.4f, -2.1f}, redId);
    addTriangle(scene, {0.7f, 0.0f, -2.2f}, {1.2f, 0.1f, -3.0f}, {0.1f, 1.4f, -2.1f}, redId);
    return scene;
}

// Every position scaled by `scale`; directions and colours unchanged.
inline Scene scaled(Scene scene, float scale) {
    scene.camera.eye *= scale;
    scene.camera.look *= scale;
    scene.camera.orthoHeight *= scale;
    for (Light &l : scene.lights) {
        l.position *= scale;
        l.radius *= scale;
    }
    for (Sphere &s : scene.spheres) {
        s.center *= scale;
        s.radius *= scale;
    }
    for (Plane &p : scene.planes)
        p.point *= scale;
    for (Triangle &t : scene.triangles)
        for (glm::vec3 &p : t.p)
            p *= scale;
    return scene;
}

} // namespace prism::test
