// Arrays past the storage-buffer range. With texel reads (the default) an array may be larger
// than maxStorageBufferRange (128 MiB on lavapipe), and then every read of it must go through
// its texel view: a storage read past the range returns zeros, which once turned the last
// triangles of a 6M-triangle scene grey (material 0) with NaN normals. The device's limit is
// lowered here so that a small scene has arrays past it.
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "render_helpers.h"
#include "scene_builders.h"

namespace prism::test {
namespace {

constexpr int kColumns = 16, kRows = 12; // one unit cell each; 4x4 pixels at 64x48
constexpr uint32_t kWidth = 64, kHeight = 48;

// A 16x12 board of cells seen by a parallel camera: even cells hold a quad (two triangles with
// vertex normals and UVs), odd cells a sphere. The first and the last cell of each kind use an
// ambient-only material, so they must look exactly alike; the others are lit, textured and
// tilted by their vertex normals so that every shading array matters.
Scene boardScene() {
    Scene scene = sceneWithDefaultMaterial();
    scene.camera.eye = {8.0f, 6.0f, 10.0f};
    scene.camera.look = {8.0f, 6.0f, 0.0f};
    scene.camera.orthoHeight = float(kRows);
    scene.ambient = glm::vec3(1.0f);
    scene.lights.push_back(Light{{8.0f, 6.0f, 20.0f}, glm::vec3(1.0f), 0.0f});
    Texture redGreen;
    redGreen.width = 2;
    redGreen.height = 1;
    redGreen.texels = {glm::vec4(1, 0, 0, 1), glm::vec4(0, 1, 0, 1)};
    scene.textures.push_back(redGreen);

    Material flat;
    flat.name = "flat"; // ambient only: the colour does not depend on where the cell is
    flat.ambient = 1.0f;
    flat.diffuse = 0.0f;
    flat.color = glm::vec3(1.0f);
    flat.texture = 0;
    uint32_t flatTextured = addMaterial(scene, flat);
    flat.name = "flat sphere";
    flat.texture = kNoTexture;
    flat.color = {0.2f, 0.4f, 0.8f};
    uint32_t flatSphere = addMaterial(scene, flat);
    uint32_t lit[3] = {addMaterial(scene, "warm", {0.9f, 0.5f, 0.2f}),
                       addMaterial(scene, "cool", {0.2f, 0.5f, 0.9f}),
                       addMaterial(scene, "textured", glm::vec3(1.0f))};
    scene.materials[lit[2]].texture = 0;

    int quads = 0, spheres = 0;
    const int quadCount = kColumns * kRows / 2, sphereCount = quadCount;
    for (int j = 0; j < kRows; ++j)
        for (int i = 0; i < kColumns; ++i) {
            glm::vec3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
            if ((i + j) % 2 == 0) {
                bool isFlat = quads == 0 || quads == quadCount - 1;
                uint32_t material = isFlat ? flatTextured : lit[quads % 3];
                glm::vec3 tilt = isFlat ? glm::vec3(0, 0, 1)
                                        : glm::normalize(glm::vec3(0.3f * float(quads % 5), 0, 1));
                for (auto [p, q, r] : {std::array{a, b, c}, std::array{a, c, d}}) {
                    addTriangle(scene, p, q, r, material);
                    TriangleShading &t = shadingFor(scene.triangles.back(), scene.triangleShading);
                    t.hasNormals = t.hasUVs = true;
                    for (int k = 0; k < 3; ++k) {
                        t.n[k] = tilt;
                        t.uv[k] = isFlat ? glm::vec2(0.25f, 0.5f) : glm::vec2(k * 0.4f, 0.5f);
                    }
                }
                ++quads;
            } else {
                bool isFlat = spheres == 0 || spheres == sphereCount - 1;
                scene.spheres.push_back(
                    Sphere{(a + c) * 0.5f, 0.4f, isFlat ? flatSphere : lit[spheres % 2]});
                ++spheres;
            }
        }
    return scene;
}

struct Pixel {
    glm::vec3 color, normal;
};

Pixel pixelAt(const TracedImage &image, int x, int y) {
    size_t i = size_t(y) * image.width + size_t(x);
    return {{image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]},
            {image.normal[3 * i], image.normal[3 * i + 1], image.normal[3 * i + 2]}};
}

// Pixel inside the lower-right triangle of the quad in cell (i, j), and near a sphere's centre.
Pixel quadPixel(const TracedImage &image, int i, int j) {
    return pixelAt(image, 4 * i + 2, 46 - 4 * j);
}
Pixel spherePixel(const TracedImage &image, int i, int j) {
    return pixelAt(image, 4 * i + 1, 45 - 4 * j);
}

class LargeScene : public GpuTest {};

TEST_F(LargeScene, ArraysPastTheStorageRangeAreReadThroughTexels) {
    Scene scene = boardScene();
    TracerOptions limited;
    limited.writeAov = true;
    limited.storageBufferLimit = 2048; // below every array but the materials and lights
    ASSERT_GT(scene.triangles.size() * sizeof(gpu::GpuTriangle), limited.storageBufferLimit);
    ASSERT_GT(scene.triangles.size() * sizeof(gpu::GpuTriangleShading), limited.storageBufferLimit);
    ASSERT_GT(scene.spheres.size() * sizeof(gpu::GpuSphere), limited.storageBufferLimit);
    TracerOptions unlimited;
    unlimited.writeAov = true;

    GpuRender past = renderGpu(context(), scene, kWidth, kHeight, 1, 2, {}, limited);
    GpuRender within = renderGpu(context(), scene, kWidth, kHeight, 1, 2, {}, unlimited);
    const TracedImage &image = past.image;
    for (float n : image.normal)
        ASSERT_FALSE(std::isnan(n)) << "a normal read as zeros";

    // The last quad and the last sphere shade exactly like the first (colour, material, normal).
    Pixel firstQuad = quadPixel(image, 0, 0), lastQuad = quadPixel(image, 15, 11);
    EXPECT_EQ(firstQuad.color, glm::vec3(1, 0, 0)) << "the flat material's red texel";
    EXPECT_EQ(lastQuad.color, firstQuad.color);
    EXPECT_EQ(lastQuad.normal, glm::vec3(0, 0, 1));
    EXPECT_EQ(firstQuad.normal, glm::vec3(0, 0, 1));
    Pixel firstSphere = spherePixel(image, 1, 0), lastSphere = spherePixel(image, 14, 11);
    EXPECT_EQ(firstSphere.color, glm::vec3(0.2f, 0.4f, 0.8f));
    EXPECT_EQ(lastSphere.color, firstSphere.color);
    EXPECT_LT(glm::length(lastSphere.normal - firstSphere.normal), 1e-5f);

    // And everywhere the image is the one traced with every array within range.
    EXPECT_EQ(image.rgba, within.image.rgba);
    EXPECT_EQ(image.normal, within.image.normal);
    EXPECT_EQ(image.depth, within.image.depth);
    EXPECT_EQ(past.frame.rays.total(), within.frame.rays.total());
}

} // namespace
} // namespace prism::test
