// Shader features that no shipped scene shows well enough for the scene regression test to
// notice a bug in them, each in a small scene of its own, held to the CPU reference. Found by
// seeding bugs (tools/scripts/mutants.sh): shadow rays that ignored planes, turned plane
// texture axes and three vertex-normal bugs passed every other test; texture filtering was
// caught by one scene only (showcase, where the textured cow is a small part of the image).
//
// Tolerance as in the scene regression test (reference_match.h), from a measurement
// (2026-12-01, these scenes at 64x48): the largest difference to the reference is 0.000002 and
// the mean under 0.0000001. Each of those seeded bugs changes 236 to 3072 of the 3072 pixels.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "reference_match.h"
#include "render_helpers.h"
#include "scene_builders.h"

namespace prism::test {
namespace {

class ShadingFeatures : public GpuTest {
protected:
    std::vector<float> expectMatchesReference(const Scene &scene) {
        return test::expectMatchesReference(context(), scene);
    }
};

// 8x8 texels, every one different and no symmetry, so that a flip, a turn or a shift of the
// texture changes the picture.
Texture patchwork() {
    Texture t;
    t.path = "patchwork";
    t.width = t.height = 8;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            t.texels.push_back({float((3 * x + y) % 8) / 7.0f, float((x + 5 * y) % 8) / 7.0f,
                                float(x * y % 7) / 6.0f, 1.0f});
    return t;
}

uint32_t addTexturedMaterial(Scene &scene, const std::string &name) {
    scene.textures.push_back(patchwork());
    Material m;
    m.name = name;
    m.color = glm::vec3(1.0f);
    m.ambient = 0.3f;
    m.diffuse = 0.7f;
    m.texture = int32_t(scene.textures.size() - 1);
    return addMaterial(scene, m);
}

// A floor and a wall facing the camera; one light in front, one behind the wall. Everything in
// view is in front of the wall, so the wall (an infinite plane) hides the second light from all
// of it: shadow rays must test planes too.
TEST_F(ShadingFeatures, PlaneBetweenALightAndASurfaceCastsAShadow) {
    Scene scene = sceneWithDefaultMaterial();
    uint32_t floor = addMaterial(scene, "floor", {0.7f, 0.7f, 0.7f});
    uint32_t wall = addMaterial(scene, "wall", {0.6f, 0.5f, 0.4f});
    uint32_t red = addMaterial(scene, "red", {0.9f, 0.2f, 0.1f});
    scene.camera.eye = {0.0f, 3.0f, 6.0f};
    scene.camera.look = {0.0f, 0.5f, -1.0f};
    scene.camera.fovDegrees = 50.0f;
    scene.planes.push_back(Plane{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, floor});
    scene.planes.push_back(Plane{{0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, 1.0f}, wall});
    scene.spheres.push_back(Sphere{{0.0f, 0.75f, 0.0f}, 0.75f, red});
    scene.lights.push_back(Light{{3.0f, 5.0f, 4.0f}, {0.6f, 0.6f, 0.6f}, 0.0f});
    Scene frontLightOnly = scene;
    scene.lights.push_back(Light{{0.0f, 3.0f, -5.0f}, {0.8f, 0.8f, 0.8f}, 0.0f});
    std::vector<float> both = expectMatchesReference(scene);
    // The hidden light adds nothing anywhere: the same image to the bit.
    EXPECT_EQ(both, renderGpu(context(), frontLightOnly, kMatchWidth, kMatchHeight).image.rgba);
}

// A textured floor seen from above, magnified: one texel spans 6x6 pixels, so bilinear
// filtering, where texel centres lie and which way the plane's texture axes run all show.
TEST_F(ShadingFeatures, TexturedPlaneMagnified) {
    Scene scene = sceneWithDefaultMaterial();
    uint32_t patch = addTexturedMaterial(scene, "patchwork");
    scene.planes.push_back(Plane{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, patch});
    scene.lights.push_back(Light{{0.3f, 4.0f, 0.2f}, {1.0f, 1.0f, 1.0f}, 0.0f});
    scene.camera.eye = {0.5f, 3.0f, 0.5f};
    scene.camera.look = {0.5f, 0.0f, 0.5f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.orthoHeight = 1.0f; // 48 pixels per unit, 8 texels per unit
    expectMatchesReference(scene);
}

// Smooth shading: diffuse, highlight and mirror ray all follow the interpolated normal.
TEST_F(ShadingFeatures, SmoothMeshWithVertexNormals) {
    Scene scene = sceneWithDefaultMaterial();
    uint32_t floor = addMaterial(scene, "floor", {0.5f, 0.55f, 0.6f});
    uint32_t red = addMaterial(scene, "red", {0.9f, 0.2f, 0.1f});
    uint32_t blue = addMaterial(scene, "blue", {0.2f, 0.3f, 0.9f});
    uint32_t shiny = addTexturedMaterial(scene, "shiny");
    scene.materials[shiny].specular = 0.6f;
    scene.materials[shiny].shininess = 24.0f;
    scene.materials[shiny].reflect = 0.4f;
    scene.camera.eye = {0.3f, 1.8f, 4.0f};
    scene.camera.look = {0.0f, 1.0f, 0.0f};
    scene.camera.fovDegrees = 45.0f;
    scene.background = {0.15f, 0.2f, 0.3f};
    scene.planes.push_back(Plane{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, floor});
    addSmoothOctahedron(scene, {0.0f, 1.1f, 0.0f}, 1.0f, shiny);
    scene.spheres.push_back(Sphere{{-1.8f, 0.5f, 0.5f}, 0.5f, red});
    scene.spheres.push_back(Sphere{{1.6f, 0.6f, -0.8f}, 0.6f, blue});
    scene.lights.push_back(Light{{-3.0f, 5.0f, 4.0f}, {1.0f, 1.0f, 1.0f}, 0.0f});
    expectMatchesReference(scene);
}

} // namespace
} // namespace prism::test
