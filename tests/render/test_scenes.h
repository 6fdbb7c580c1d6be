#pragma once
// The scene the stability tests render, built with the shared helpers (tests/support).
#include <cstdint>

#include "scene/scene.h"
#include "scene_builders.h"
#include "scene_transform.h"

namespace prism::test {

// A floor, a mirror sphere, a glass sphere, a diffuse sphere resting on the floor and an
// octahedron: contact shadows, reflections and refraction all in view. Coordinates are
// multiples of 1/16, so moving the scene by 1e4 (float spacing 2^-10 there) is exact and any
// difference comes from the tracer, not from moved geometry.
inline Scene stabilityScene() {
    Scene scene = sceneWithDefaultMaterial();
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

} // namespace prism::test
