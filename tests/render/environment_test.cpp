// `environment`: what rays that miss everything see (docs/scene-format.md), on the shader with
// validation on and on the CPU reference, checked against the image's own texels.
#include <cmath>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "gradient_sky.h"
#include "render_helpers.h"
#include "scene_builders.h"

namespace prism::test {
namespace {

class Environment : public GpuTest {};

constexpr int kColumns = 8;

// An 8 x 2 lat-long image, each column its own colour and both rows alike, turned by 22.5
// degrees: a direction along -z then samples column 3's centre exactly, one along +x column
// 5's (u = 0.5 + (atan2(x, -z) - rotation) / 2pi), so bilinear filtering has nothing to blend.
glm::vec3 column(int c) {
    return {0.1f + 0.1f * float(c), 0.5f, 1.0f - 0.1f * float(c)};
}

Scene skyScene() {
    Scene scene = sceneWithDefaultMaterial();
    Texture sky;
    sky.path = "sky";
    sky.width = kColumns;
    sky.height = 2;
    for (int row = 0; row < 2; ++row)
        for (int c = 0; c < kColumns; ++c)
            sky.texels.push_back(glm::vec4(column(c), 1.0f));
    scene.textures.push_back(sky);
    scene.environment.texture = 0;
    scene.environment.intensity = 2.0f;
    scene.environment.rotateDegrees = 22.5f;
    scene.background = {1.0f, 0.0f, 1.0f}; // must not be seen
    scene.camera.eye = {0.0, 0.0, 0.0};
    scene.camera.look = {0.0, 0.0, -1.0};
    return scene;
}

// The centre of a 9x9 image looks exactly along the camera's forward axis.
glm::vec3 centre(const std::vector<float> &rgba) {
    size_t p = 4 * (4 * 9 + 4);
    return {rgba[p], rgba[p + 1], rgba[p + 2]};
}

void expectColour(glm::vec3 got, glm::vec3 want) {
    EXPECT_NEAR(got.x, want.x, 1e-5f);
    EXPECT_NEAR(got.y, want.y, 1e-5f);
    EXPECT_NEAR(got.z, want.z, 1e-5f);
}

TEST_F(Environment, SeenStraightAndNotAsLight) {
    Scene scene = skyScene();
    // A diffuse sphere in view, no lights, no ambient: the sky must not light it.
    uint32_t clay = addMaterial(scene, "clay", {0.8f, 0.8f, 0.8f});
    scene.materials[clay].ambient = 0.0f;
    scene.spheres.push_back(Sphere{{0.0, 3.0, -6.0}, 1.0f, clay});
    TracedImage gpu = renderGpu(context(), scene, 9, 9, 1, 3).image;
    std::vector<float> cpu = renderCpu(scene, 9, 9, 1, 3);
    expectColour(centre(gpu.rgba), 2.0f * column(3));
    expectColour(centre(cpu), 2.0f * column(3));
    size_t sphere = 4 * (1 * 9 + 4); // row 1 looks up at the sphere
    EXPECT_TRUE(std::isfinite(gpu.rgba[sphere]));
    EXPECT_EQ(glm::vec3(gpu.rgba[sphere], gpu.rgba[sphere + 1], gpu.rgba[sphere + 2]),
              glm::vec3(0.0f));
}

TEST_F(Environment, SeenThroughAMirror) {
    Scene scene = skyScene();
    uint32_t mirror = addMaterial(scene, "mirror", {0.2f, 0.2f, 0.2f}, 1.0f);
    scene.materials[mirror].ambient = 0.0f;
    scene.materials[mirror].diffuse = 0.0f;
    // At 45 degrees across the view: the centre ray (-z) leaves it along +x.
    scene.planes.push_back(Plane{{0.0, 0.0, -2.0}, glm::normalize(glm::vec3(1, 0, 1)), mirror});
    TracedImage gpu = renderGpu(context(), scene, 9, 9, 1, 2).image;
    std::vector<float> cpu = renderCpu(scene, 9, 9, 1, 2);
    expectColour(centre(gpu.rgba), 2.0f * column(5));
    expectColour(centre(cpu), 2.0f * column(5));
    // With depth 1 the reflected ray is not traced: the mirror is black, not the sky.
    TracedImage shallow = renderGpu(context(), scene, 9, 9, 1, 1).image;
    expectColour(centre(shallow.rgba), glm::vec3(0.0f));
}

// The sky above is the image's top row, the sky below its bottom row: rays up, down, at the
// poles and level each read the row their elevation names, on both renderers. (The sky of the
// tests above has two identical rows, so it could not see the vertical axis turned over.)
TEST_F(Environment, RowsFollowTheElevation) {
    struct View {
        glm::dvec3 dir;
        glm::vec3 up;
    };
    const View views[] = {
        {{0.0, 0.0, -1.0}, {0, 1, 0}},                  // level: v = 1/2
        {{0.0, std::sin(0.5), -std::cos(0.5)}, {0, 1, 0}}, // up by 0.5 rad
        {{1.0, -1.0, 0.0}, {0, 1, 0}},                  // down by 45 degrees, towards +x
        {{0.0, 1.0, 0.0}, {0, 0, -1}},                  // the zenith: the top row
        {{0.0, -1.0, 0.0}, {0, 0, 1}},                  // the nadir: the bottom row
        {{-0.3, 0.9, 0.2}, {0, 1, 0}},                  // steep, off every axis
    };
    for (const View &view : views) {
        Scene scene = sceneWithDefaultMaterial();
        addGradientSky(scene);
        scene.camera = cameraAlong(view.dir, view.up);
        double want = gradientSkyRed(view.dir);
        SCOPED_TRACE("direction " + std::to_string(view.dir.x) + " " +
                     std::to_string(view.dir.y) + " " + std::to_string(view.dir.z));
        glm::vec3 gpu = centre(renderGpu(context(), scene, 9, 9, 1, 1).image.rgba);
        glm::vec3 cpu = centre(renderCpu(scene, 9, 9, 1, 1));
        // The reference works in double. The shader's asin is Vulkan's, within 4096 ulps of the
        // angle (the spec's "inherited from atan2"): 4.9e-4 radians near pi/2, 1.6e-4 of v
        // (measured: 1.2e-4 looking up at 64 degrees). A sky upside down is off by 0.1 or more
        // in every view here but the level one, and that one's row is checked by the tests above.
        EXPECT_NEAR(cpu.r, want, 1e-6);
        EXPECT_NEAR(cpu.g, 1.0 - want, 1e-6);
        EXPECT_NEAR(gpu.r, want, 1.6e-4);
        EXPECT_NEAR(gpu.g, 1.0 - want, 1.6e-4);
        for (glm::vec3 got : {gpu, cpu})
            EXPECT_NEAR(got.b, 0.25, 1e-6);
    }
}

} // namespace
} // namespace prism::test
