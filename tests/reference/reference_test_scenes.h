#pragma once
// The scene the CPU reference's renderer tests render, built with the shared helpers
// (tests/support).
#include <cstdint>

#include "scene/scene.h"
#include "scene_builders.h"

namespace prism::test {

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
    uint32_t redId = addMaterial(scene, "red", {0.9f, 0.2f, 0.1f});
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

} // namespace prism::test
