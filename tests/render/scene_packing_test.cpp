// The host's packing of the scene into std430 arrays (no device needed).
#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "render/frame_params.h"
#include "render/scene_packing.h"
#include "render/tracer_features.h"
#include "scene/primitive_ids.h"
#include "shared/trace_interface.h"
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
    scene.materials[2].normalMap = 0;
    scene.materials[3].bumpMap = 1;
    scene.materials[3].bumpScale = -0.25f;
    Grid grid = buildGrid(scene, {});
    PackedScene packed = packScene(scene, grid);

    // Read back through the accessors the shader uses (shared/gpu_types.h).
    EXPECT_EQ(packed.header.counts, glm::uvec4(3, 1, 8, 1));
    ASSERT_EQ(packed.planes.size(), 1u);
    EXPECT_EQ(packed.planes[0].normalOffset, glm::vec4(0, 1, 0, 0));
    EXPECT_EQ(gpu::planeMaterial(packed.planes[0]), 1u); // "floor"
    EXPECT_EQ(gpu::sphereMaterial(packed.spheres[1]), 3u);
    EXPECT_EQ(gpu::triangleMaterial(packedTriangle(packed, 0)), 5u);
    const Material &textured = scene.materials[2];
    const gpu::GpuMaterial &m = packed.materials[2];
    EXPECT_EQ(gpu::materialColor(m), textured.color);
    EXPECT_EQ(gpu::materialAmbient(m), textured.ambient);
    EXPECT_EQ(gpu::materialDiffuse(m), textured.diffuse);
    EXPECT_EQ(gpu::materialSpecular(m), textured.specular);
    EXPECT_EQ(gpu::materialShininess(m), textured.shininess);
    EXPECT_EQ(gpu::materialReflect(m), textured.reflect);
    EXPECT_EQ(gpu::materialTransmit(m), textured.transmit);
    EXPECT_EQ(gpu::materialIor(m), textured.ior);
    EXPECT_TRUE(gpu::materialHasTexture(m));
    EXPECT_EQ(gpu::materialTexture(m), 1u);
    EXPECT_FALSE(gpu::materialHasTexture(packed.materials[1]));
    EXPECT_TRUE(gpu::materialHasNormalMap(m));
    EXPECT_EQ(gpu::materialNormalMap(m), 0u);
    EXPECT_FALSE(gpu::materialHasBumpMap(m));
    const gpu::GpuMaterial &bumpy = packed.materials[3];
    EXPECT_FALSE(gpu::materialHasNormalMap(bumpy));
    EXPECT_TRUE(gpu::materialHasBumpMap(bumpy));
    EXPECT_EQ(gpu::materialBumpMap(bumpy), 1u);
    EXPECT_EQ(gpu::materialBumpScale(bumpy), -0.25f);
    EXPECT_EQ(gpu::materialBumpScale(packed.materials[1]), 1.0f);
    EXPECT_EQ(gpu::lightPosition(packed.lights[0]), glm::vec3(scene.lights[0].position));
    EXPECT_EQ(gpu::lightRadius(packed.lights[0]), scene.lights[0].radius);
    EXPECT_EQ(gpu::lightColor(packed.lights[0]), scene.lights[0].color);
    EXPECT_EQ(gpu::textureFirstTexel(packed.textures[1]), 2u); // after the first texture's 2
    EXPECT_EQ(gpu::textureWidth(packed.textures[1]), 2u);
    EXPECT_EQ(gpu::textureHeight(packed.textures[1]), 1u);
    // A textured material makes the tracer read shading data for every triangle hit.
    ASSERT_TRUE(packed.triangleShading);
    std::vector<gpu::GpuTriangleShading> shading(scene.triangles.size());
    writeTriangleShading(packed, shading);
    EXPECT_FALSE(gpu::shadingHasNormals(shading[0]));
    EXPECT_FALSE(gpu::shadingHasUVs(shading[0]));
    EXPECT_EQ(packed.texels.size(), 4u);
    EXPECT_EQ(packed.cellStart.size(), size_t(packed.header.gridRes.w) + 1);
    EXPECT_EQ(packed.cellStart.back(), packed.cellPrimitives.size());
}

TEST(ScenePacking, ShadingArrayOnlyWhereTheTracerReadsIt) {
    Scene scene = stabilityScene(); // no normals, UVs or textures
    Grid grid = buildGrid(scene, {});
    EXPECT_FALSE(packScene(scene, grid).triangleShading);
    std::vector<gpu::GpuTriangleShading> none;
    writeTriangleShading(packScene(scene, grid), none); // nothing to write, and no error
    shadingFor(scene.triangles[3], scene.triangleShading).hasUVs = true;
    PackedScene packed = packScene(scene, grid);
    ASSERT_TRUE(packed.triangleShading);
    std::vector<gpu::GpuTriangleShading> shading(scene.triangles.size());
    writeTriangleShading(packed, shading);
    EXPECT_TRUE(gpu::shadingHasUVs(shading[3]));
    EXPECT_FALSE(gpu::shadingHasNormals(shading[3]));
    std::vector<gpu::GpuTriangleShading> tooFew(scene.triangles.size() - 1);
    EXPECT_THROW(writeTriangleShading(packed, tooFew), Error);
}

// Grid ids: spheres first, then triangles; the header carries the ranges the tracer decodes.
TEST(ScenePacking, PrimitiveIdRangesFollowTheKinds) {
    Scene scene = stabilityScene();
    PrimitiveIds ids(scene);
    EXPECT_EQ(ids.first(gpu::kKindSphere), 0u);
    EXPECT_EQ(ids.first(gpu::kKindTriangle), 3u);
    EXPECT_EQ(ids.count(), 11u);
    PrimitiveIds::Decoded d = ids.decode(5);
    EXPECT_EQ(d.kind, gpu::kKindTriangle);
    EXPECT_EQ(d.index, 2u);
    EXPECT_EQ(ids.decode(2).kind, gpu::kKindSphere);
    Grid grid = buildGrid(scene, {});
    EXPECT_EQ(packScene(scene, grid).header.idEnd, ids.end);
}

// The adaptive grid's cell boxes go up with each cell's first primitive-list entry in w, where
// the walk reads it (gpu::cellBoxFirstPrimitive); the boxes themselves are unchanged.
TEST(ScenePacking, AdaptiveCellBoxesCarryTheirFirstPrimitive) {
    Scene scene = stabilityScene();
    Grid grid = buildGrid(scene, parseGridOption("adaptive"));
    ASSERT_TRUE(grid.adaptive());
    PackedScene packed = packScene(scene, grid);
    ASSERT_EQ(packed.cellBoxes.size(), grid.cellBoxes.size());
    std::vector<glm::uvec4> boxes(grid.cellBoxes.size());
    writeCellBoxes(packed, boxes);
    for (size_t c = 0; c < grid.cellBoxes.size(); ++c) {
        EXPECT_EQ(gpu::cellBoxFirstPrimitive(boxes[c]), grid.cellStart[c]);
        EXPECT_EQ(gpu::cellBoxMin(boxes[c]), gpu::cellBoxMin(grid.cellBoxes[c]));
        EXPECT_EQ(gpu::cellBoxMax(boxes[c]), gpu::cellBoxMax(grid.cellBoxes[c]));
    }
    std::vector<glm::uvec4> tooFew(grid.cellBoxes.size() - 1);
    EXPECT_THROW(writeCellBoxes(packed, tooFew), Error);
}

// The triangle array is the scene's triangles, then each prototype's, written from the scene
// as the device reads them: float positions, the material in the first vertex's w.
TEST(ScenePacking, TrianglesWrittenFromTheSceneInListOrder) {
    Scene scene = stabilityScene();
    scene.prototypes.push_back(MeshPrototype{"copy", scene.triangles, scene.triangleShading});
    scene.prototypes[0].triangles[1].material = 2;
    scene.instances.push_back(Instance{});
    Grid grid = buildGrid(scene, {});
    PackedScene packed = packScene(scene, grid);
    size_t own = scene.triangles.size(), total = own + scene.prototypes[0].triangles.size();
    ASSERT_EQ(packed.triangleCount, total);
    std::vector<gpu::GpuTriangle> triangles(total);
    writeTriangles(packed, triangles);
    for (size_t i = 0; i < total; ++i) {
        const Triangle &t = i < own ? scene.triangles[i] : scene.prototypes[0].triangles[i - own];
        EXPECT_EQ(glm::vec3(triangles[i].v0), glm::vec3(t.p[0])) << i;
        EXPECT_EQ(glm::vec3(triangles[i].v1), glm::vec3(t.p[1])) << i;
        EXPECT_EQ(glm::vec3(triangles[i].v2), glm::vec3(t.p[2])) << i;
        EXPECT_EQ(gpu::triangleMaterial(triangles[i]), t.material) << i;
        gpu::GpuTriangle one = packedTriangle(packed, i);
        EXPECT_EQ(std::memcmp(&triangles[i], &one, sizeof one), 0) << i;
    }
    EXPECT_THROW(packedTriangle(packed, total), Error);
    std::vector<gpu::GpuTriangle> tooMany(total + 1);
    EXPECT_THROW(writeTriangles(packed, tooMany), Error);
}

// The grid's arrays are viewed where the packing leaves them as they are (no copy), and
// copied where it changes them: the prototypes' grids appended after the scene grid's.
TEST(ScenePacking, GridArraysViewedUnlessChanged) {
    Scene scene = stabilityScene();
    Grid grid = buildGrid(scene, parseGridOption("adaptive"));
    PackedScene packed = packScene(scene, grid);
    EXPECT_EQ(packed.cellStart.data(), grid.cellStart.data());
    EXPECT_EQ(packed.cellPrimitives.data(), grid.cellPrimitives.data());
    EXPECT_EQ(packed.gridEntries.data(), grid.entries.data());
    EXPECT_EQ(packed.cellBoxes.data(), grid.cellBoxes.data());
    // Moved, the packed scene still views the same arrays.
    PackedScene moved = std::move(packed);
    EXPECT_EQ(moved.cellStart.data(), grid.cellStart.data());

    Scene withInstance = scene;
    withInstance.prototypes.push_back(
        MeshPrototype{"copy", scene.triangles, scene.triangleShading});
    withInstance.instances.push_back(Instance{});
    Grid instanced = buildGrid(withInstance, {});
    PackedScene appended = packScene(withInstance, instanced);
    ASSERT_EQ(appended.cellStart.size(),
              instanced.cellStart.size() + instanced.meshGrids[0].cellStart.size());
    EXPECT_EQ(appended.cellStart.data(), appended.ownedCellStart.data());
    EXPECT_TRUE(std::equal(instanced.cellStart.begin(), instanced.cellStart.end(),
                           appended.cellStart.begin()));
    PackedScene appendedMoved = std::move(appended);
    EXPECT_EQ(appendedMoved.cellStart.data(), appendedMoved.ownedCellStart.data());
    EXPECT_EQ(appendedMoved.cellPrimitives.data(), appendedMoved.ownedCellPrimitives.data());
}

TEST(TracerFeatures, FollowTheScene) {
    Scene scene = stabilityScene();
    TracerFeatures f = featuresOf(scene);
    EXPECT_TRUE(f.has(gpu::kKindSphere) && f.has(gpu::kKindPlane) && f.has(gpu::kKindTriangle));
    EXPECT_TRUE(f.reflection && f.transmission);
    EXPECT_FALSE(f.textures || f.areaLights || f.vertexNormals || f.environment || f.surfaceMaps);
    scene.textures.push_back(Texture{"sky", 1, 1, {glm::vec4(1.0f)}});
    scene.environment.texture = 0;
    EXPECT_TRUE(featuresOf(scene).environment);
    EXPECT_FALSE(featuresOf(scene).textures) << "no material uses it";
    scene.materials[1].bumpMap = 0;
    EXPECT_TRUE(featuresOf(scene).surfaceMaps);
    EXPECT_FALSE(featuresOf(scene).textures) << "a bump map is not a colour texture";
    scene.materials[1].bumpMap = kNoTexture;
    scene.materials[2].normalMap = 0;
    EXPECT_TRUE(featuresOf(scene).surfaceMaps);
    scene.materials[3].transmit = 0.0f;
    EXPECT_FALSE(featuresOf(scene).transmission);
    f.maxDepth = 5;
    f.texelBuffers = true;
    std::map<uint32_t, uint32_t> constants;
    for (vk::SpecializationConstant c : f.specialization())
        EXPECT_TRUE(constants.emplace(c.id, c.value).second) << "constant_id " << c.id << " twice";
    EXPECT_EQ(constants.size(), 20u); // every constant_id of shared/trace_interface.h
    EXPECT_EQ(constants.at(gpu::kSpecCellTriangles), 0u) << "the scene has spheres";
    EXPECT_EQ(constants.at(gpu::kSpecAdaptiveGrid), 0u);
    EXPECT_EQ(constants.at(gpu::kSpecResumable), 0u) << "resumable only after a cut";
    EXPECT_EQ(constants.at(gpu::kSpecResumeLaneBudget), gpu::kResumeLaneBudget);
    EXPECT_EQ(constants.at(gpu::kSpecProfileWalkDetail), 0u);
    EXPECT_EQ(constants.at(gpu::kSpecKinds), 0b1011u) << "spheres, triangles and planes";
    EXPECT_EQ(constants.at(gpu::kSpecStackSize), 9u) << "stack holds 2 * depth - 1 rays";
    EXPECT_EQ(constants.at(gpu::kSpecTexelBuffers), 1u) << "texel-buffer reads";
    EXPECT_EQ(constants.at(gpu::kSpecHasTextures), 0u);
    EXPECT_EQ(constants.at(gpu::kSpecHasSurfaceMaps), 0u);
    EXPECT_EQ(constants.at(gpu::kSpecHasTransmission), 1u);
    EXPECT_EQ(constants.at(gpu::kSpecFixedRayOffset), 0u) << "Prism's relative offset";
    EXPECT_EQ(constants.at(gpu::kSpecTriangleTest), gpu::kTriangleTestWatertight);
}

// The studies' stand-ins for replaced methods (docs/studies) are chosen only when asked for;
// the fixed offset travels as the float's bits, and a negative or NaN one is refused.
TEST(TracerFeatures, StudiesVariantsAreOptIn) {
    Scene scene = stabilityScene();
    Grid grid = buildGrid(scene);
    auto constantsOf = [&](const TracerOptions &options) {
        std::map<uint32_t, uint32_t> constants;
        for (vk::SpecializationConstant c : chooseFeatures(scene, grid, options).specialization())
            constants[c.id] = c.value;
        return constants;
    };
    TracerOptions options;
    EXPECT_EQ(constantsOf(options).at(gpu::kSpecFixedRayOffset), 0u);
    options.fixedRayOffset = 0.01f;
    options.mollerTrumbore = true;
    auto constants = constantsOf(options);
    EXPECT_EQ(constants.at(gpu::kSpecFixedRayOffset), std::bit_cast<uint32_t>(0.01f));
    EXPECT_EQ(constants.at(gpu::kSpecTriangleTest), gpu::kTriangleTestMollerTrumbore);
    for (float bad : {-1e-4f, std::numeric_limits<float>::quiet_NaN(),
                      std::numeric_limits<float>::infinity()}) {
        options.fixedRayOffset = bad;
        EXPECT_THROW(chooseFeatures(scene, grid, options), Error) << bad;
    }
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
    EXPECT_EQ(gpu::frameLoopProbe(p), gpu::kLoopProbeRuns) << "loop_limit.glsl's probe";
}

} // namespace
} // namespace prism::test
