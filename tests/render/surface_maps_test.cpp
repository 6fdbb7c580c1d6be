// Normal and bump maps (docs/scene-format.md, "Normal and bump maps") on a sphere, a plane, a
// smooth mesh and a flat triangle pair (one with texture coordinates, one seen from behind), in
// the shader with validation on and held to the CPU reference, which computes the tangent frames
// and slopes again in double.
//
// Shader against reference: the tolerance of the scene regression test (reference_match.h: a
// pixel differs when a channel is off by more than 0.02; 2 such pixels may flip on float
// rounding, a third, or a mean over 0.001, fails). Measured (2026-12-02, 64x48): no pixel over
// 0.02 (largest 0.012), mean under 0.000013. The largest differences come from the mirror term:
// bent normals send reflected rays grazing past silhouettes, where float and double may pick
// different objects (with reflect 0.2 one pixel was off by 0.041, with none the largest was
// 0.004), so the material reflects only 0.1. Each map must also change the picture against the
// same scene without it, so a map that is ignored fails: measured 74-82% of the pixels change
// by more than 0.02.
#include <cmath>
#include <cstdint>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "reference_match.h"
#include "render_helpers.h"
#include "scene/texture_loader.h"
#include "scene_builders.h"
#include "temp_dir.h"

namespace prism::test {
namespace {

constexpr uint32_t kWidth = kMatchWidth, kHeight = kMatchHeight;
// A map must change at least this share of the 3072 pixels (measured 74-82%, above).
constexpr double kMinChangedFraction = 0.2;

constexpr double kTwoPi = 6.283185307179586;

// A 16 x 16 texture whose texel in column x and row y (from the top) is texel(x', y'), with
// x' = (x + 0.5) / 16 and y' = (y + 0.5) / 16 its centre.
template <typename Texel> Texture texture16(const char *name, Texel texel) {
    Texture t{name, 16, 16, {}};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            t.texels.push_back(texel((x + 0.5) / 16.0, (y + 0.5) / 16.0));
    return t;
}

// Tangent-space normals leaning one way along u and another along v, so that a swapped or
// mirrored tangent frame, or a flipped v, shows. Stored as (n + 1) / 2.
Texture wavyNormals() {
    return texture16("wavy normals", [](double x, double y) {
        glm::dvec3 n = glm::normalize(
            glm::dvec3(0.7 * std::sin(kTwoPi * x), 0.3 + 0.4 * std::cos(2.0 * kTwoPi * y), 1.0));
        return glm::vec4(glm::vec3(0.5 * n + 0.5), 1.0f);
    });
}

// Heights, smooth and wrapping, with different waves along u and v; grey with a tint, so that
// the luminance weights matter.
Texture rollingHeights() {
    return texture16("rolling heights", [](double x, double y) {
        double h = 0.5 + 0.25 * std::sin(kTwoPi * x) + 0.2 * std::cos(kTwoPi * (2.0 * y + x));
        return glm::vec4(float(h), float(0.9 * h), float(1.1 * h), 1.0f);
    });
}

Material mappedMaterial() {
    return Material{.name = "mapped",
                    .color = {0.8f, 0.7f, 0.5f},
                    .ambient = 0.15f,
                    .diffuse = 0.85f,
                    .specular = 0.5f,
                    .shininess = 24.0f,
                    .reflect = 0.1f};
}

// A floor, a sphere, a smooth octahedron and a wall of two flat triangles (the second without
// texture coordinates, and wound so that the camera sees its back: maps bend the normal of the
// side it points to, then it turns), all of material 1; two lights, one low so that shading
// leans.
Scene sceneOf(const Material &material) {
    Scene scene = sceneWithDefaultMaterial();
    uint32_t m = addMaterial(scene, material);
    scene.camera.eye = {0.4, 2.2, 4.5};
    scene.camera.look = {0.0, 0.8, 0.0};
    scene.camera.fovDegrees = 50.0f;
    scene.background = {0.1f, 0.15f, 0.25f};
    scene.planes.push_back(Plane{{0.0, 0.0, 0.0}, {0.0f, 1.0f, 0.0f}, m});
    scene.spheres.push_back(Sphere{{-1.3, 0.8, 0.3}, 0.8f, m});
    addSmoothOctahedron(scene, {1.2f, 0.9f, 0.2f}, 0.9f, m);
    addTriangle(scene, {-2.5f, 0.0f, -1.5f}, {2.5f, 0.0f, -1.5f}, {2.5f, 2.5f, -1.5f}, m);
    TriangleShading &shading = shadingFor(scene.triangles.back(), scene.triangleShading);
    shading.hasUVs = true;
    shading.uv[0] = {0.0f, 0.0f};
    shading.uv[1] = {2.0f, 0.0f};
    shading.uv[2] = {2.0f, 1.0f};
    addTriangle(scene, {-2.5f, 0.0f, -1.5f}, {-2.5f, 2.5f, -1.5f}, {2.5f, 2.5f, -1.5f}, m);
    scene.lights.push_back(Light{{-3.0, 4.0, 3.0}, {0.9f, 0.9f, 0.9f}, 0.0f});
    scene.lights.push_back(Light{{3.0, 1.2, 2.0}, {0.5f, 0.45f, 0.4f}, 0.0f});
    return scene;
}

class SurfaceMaps : public GpuTest {
protected:
    std::vector<float> expectMatchesReference(const Scene &scene) {
        return test::expectMatchesReference(context(), scene);
    }
    // `mapped` must differ from the unmapped scene's image in many pixels.
    void expectChangesThePicture(const std::vector<float> &mapped) {
        std::vector<float> plain =
            renderGpu(context(), sceneOf(mappedMaterial()), kWidth, kHeight).image.rgba;
        ImageDifference d = compareImages(mapped, plain, kMatchPixelThreshold);
        EXPECT_GE(d.differingFraction(), kMinChangedFraction) << describe(d);
    }
};

TEST_F(SurfaceMaps, NormalMapMatchesTheReference) {
    Material m = mappedMaterial();
    Scene scene = sceneOf(m);
    scene.textures.push_back(wavyNormals());
    scene.materials[1].normalMap = 0;
    expectChangesThePicture(expectMatchesReference(scene));
}

TEST_F(SurfaceMaps, BumpMapMatchesTheReference) {
    Scene scene = sceneOf(mappedMaterial());
    scene.textures.push_back(rollingHeights());
    scene.materials[1].bumpMap = 0;
    scene.materials[1].bumpScale = 0.15f;
    expectChangesThePicture(expectMatchesReference(scene));
}

// Both maps on one material: the bump's slopes are taken from the normal map's x and y.
TEST_F(SurfaceMaps, BothMapsMatchTheReference) {
    Scene scene = sceneOf(mappedMaterial());
    scene.textures.push_back(wavyNormals());
    scene.textures.push_back(rollingHeights());
    scene.materials[1].normalMap = 0;
    scene.materials[1].bumpMap = 1;
    scene.materials[1].bumpScale = -0.1f;
    expectChangesThePicture(expectMatchesReference(scene));
}

// Glass refracts about the shading normal, so smooth and mapped normals bend what is seen
// through it: the sphere and the smooth octahedron made of glass in front of the mapped floor
// and wall (each material's own maps), held to the reference with the same tolerance.
Material glassMaterial() {
    Material glass = opticalMaterial("glass", 0.1f, 0.85f, 1.5f);
    glass.specular = 0.4f;
    glass.shininess = 48.0f;
    return glass;
}

Scene glassObjectsScene(const Material &glass) {
    Scene scene = sceneOf(mappedMaterial());
    uint32_t g = addMaterial(scene, glass);
    scene.spheres[0].material = g;
    for (size_t t = 0; t < 8; ++t) // the octahedron's faces (sceneOf adds them first)
        scene.triangles[t].material = g;
    return scene;
}

TEST_F(SurfaceMaps, SmoothGlassMatchesTheReference) {
    Scene scene = glassObjectsScene(glassMaterial());
    ASSERT_TRUE(scene.shadingOf(0).hasNormals);
    expectMatchesReference(scene);
}

TEST_F(SurfaceMaps, BumpMappedGlassMatchesTheReference) {
    Scene scene = glassObjectsScene(glassMaterial());
    scene.textures.push_back(rollingHeights());
    scene.materials[2].bumpMap = 0;
    scene.materials[2].bumpScale = 0.15f;
    std::vector<float> bumped = expectMatchesReference(scene);
    // The bumps must show through the glass: against the unmapped glass, many pixels change.
    ImageDifference d = compareImages(
        bumped,
        renderGpu(context(), glassObjectsScene(glassMaterial()), kWidth, kHeight).image.rgba,
        kMatchPixelThreshold);
    EXPECT_GE(d.differingFraction(), 0.05) << describe(d);
}

// A normal map of (0.5, 0.5, 1) everywhere is the unbent normal (0, 0, 1), and a bump map with
// multiplier 0 has no slope: the image must be the one without maps, on both backends. Written
// as a float EXR so that 0.5 is exact (8 bits cannot hold it: 128/255 leans the normal by
// 0.4 degrees). Tolerance 1e-5: the only change is renormalising a unit normal in float (an ulp
// or two, ~1e-7, raised to shininess 24 in the highlight). Measured: largest 0.000001 on the
// shader, 0 on the reference.
TEST_F(SurfaceMaps, FlatMapsChangeNothing) {
    TempDir dir;
    std::filesystem::path flat = dir.path() / "flat.exr";
    {
        auto out = OIIO::ImageOutput::create(flat.string());
        ASSERT_TRUE(out) << OIIO::geterror();
        std::vector<float> pixels;
        for (int p = 0; p < 4 * 4; ++p)
            pixels.insert(pixels.end(), {0.5f, 0.5f, 1.0f});
        ASSERT_TRUE(out->open(flat.string(), OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::FLOAT)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
        out->close();
    }
    Scene plain = sceneOf(mappedMaterial());
    Scene mapped = plain;
    TextureCache cache;
    mapped.materials[1].normalMap = cache.load(flat, mapped, TexelMeaning::Data);
    ASSERT_EQ(mapped.textures[0].texels[5], glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));
    mapped.textures.push_back(rollingHeights());
    mapped.materials[1].bumpMap = 1;
    mapped.materials[1].bumpScale = 0.0f;
    constexpr double kRenormalisation = 1e-5;
    ImageDifference gpu =
        compareImages(renderGpu(context(), mapped, kWidth, kHeight).image.rgba,
                      renderGpu(context(), plain, kWidth, kHeight).image.rgba, kRenormalisation);
    EXPECT_EQ(gpu.differing, 0u) << describe(gpu);
    EXPECT_EQ(gpu.nonFinite, 0u);
    ImageDifference cpu = compareImages(renderCpu(mapped, kWidth, kHeight),
                                        renderCpu(plain, kWidth, kHeight), kRenormalisation);
    EXPECT_EQ(cpu.differing, 0u) << describe(cpu);
    EXPECT_EQ(cpu.nonFinite, 0u);
}

} // namespace
} // namespace prism::test
