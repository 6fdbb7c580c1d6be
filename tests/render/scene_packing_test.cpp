// The host's packing of the scene into std430 arrays (no device needed).
#include <gtest/gtest.h>

#include "render/frame_params.h"
#include "render/scene_packing.h"
#include "render/tracer_features.h"
#include "test_scenes.h"

namespace prism::test {
namespace {

TEST(ScenePacking, CarriesEveryArrayAndIndex) {
    Scene scene = stabilityScene();
    Texture texture;
    texture.width = 2;
    texture.height = 1;
    texture.texels = {glm::vec4(1.0f), glm::vec4(0.5f)};
    scene.textures = {texture, texture};
    scene.materials[2].texture = 1;
    Grid grid = buildGrid(scene, {});
    PackedScene packed = packScene(scene, grid);

    EXPECT_EQ(packed.header.counts, glm::uvec4(3, 1, 8, 1));
    ASSERT_EQ(packed.planes.size(), 1u);
    EXPECT_EQ(packed.planes[0].normalOffset, glm::vec4(0, 1, 0, 0));
    EXPECT_EQ(packed.planes[0].point.w, 1.0f); // material "floor"
    EXPECT_EQ(packed.spheres[1].material.x, 3u);
    EXPECT_EQ(packed.triangles[0].v0.w, 5.0f);
    EXPECT_TRUE(packed.triangleShading.empty()) << "no normals or UVs: no shading array";
    EXPECT_EQ(packed.materials[2].optics.z, 1.0f);
    EXPECT_EQ(packed.textures[1].info, glm::uvec4(2, 2, 1, 0)); // second texture starts at 2
    EXPECT_EQ(packed.texels.size(), 4u);
    EXPECT_EQ(packed.cellStart.size(), size_t(packed.header.gridRes.w) + 1);
    EXPECT_EQ(packed.cellStart.back(), packed.cellPrimitives.size());
}

TEST(TracerFeatures, FollowTheScene) {
    Scene scene = stabilityScene();
    TracerFeatures f = featuresOf(scene);
    EXPECT_TRUE(f.spheres && f.planes && f.triangles && f.reflection && f.transmission);
    EXPECT_FALSE(f.textures || f.areaLights || f.vertexNormals);
    scene.materials[3].transmit = 0.0f;
    EXPECT_FALSE(featuresOf(scene).transmission);
    f.maxDepth = 5;
    f.texelBuffers = true;
    std::vector<uint32_t> constants = f.specialization();
    ASSERT_EQ(constants.size(), 13u); // constant_id 0..12 in shaders/bindings.glsl
    EXPECT_EQ(constants[11], 9u) << "stack holds 2 * depth - 1 rays";
    EXPECT_EQ(constants[12], 1u) << "texel-buffer reads";
}

TEST(FrameParams, FollowTheCameraModel) {
    Camera camera;
    camera.eye = {0, 0, 5};
    camera.look = {0, 0, 0};
    camera.fovDegrees = 90.0f;
    gpu::GpuFrameParams p = makeFrameParams(camera, 200, 100, 1, 5);
    EXPECT_NEAR(p.forward.z, -1.0f, 1e-7f);
    EXPECT_NEAR(p.du.x, 2.0f, 1e-6f); // tan(45) * aspect 2
    EXPECT_NEAR(p.dv.y, 1.0f, 1e-6f);
    camera.orthoHeight = 4.0f;
    p = makeFrameParams(camera, 200, 100, 1, 5);
    EXPECT_EQ(p.eye.w, 1.0f);
    EXPECT_NEAR(p.du.x, 4.0f, 1e-6f); // H/2 * aspect
    EXPECT_NEAR(p.dv.y, 2.0f, 1e-6f);
}

} // namespace
} // namespace prism::test
