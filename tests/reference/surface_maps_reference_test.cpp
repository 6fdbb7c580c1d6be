// Tangent frames, bump slopes and mapped normals of the reference (surface_maps_reference.cpp)
// against values worked out by hand from docs/scene-format.md, "Normal and bump maps": the shader
// is held to the reference, so a misread convention here would pass every image test.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "expect_near.h"
#include "reference/surface_maps_reference.h"
#include "scene_builders.h"

namespace prism::reference {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using test::expectNear;

// One texel holding tangent-space normal `n`, stored as (n + 1) / 2.
Texture normalTexel(glm::dvec3 n) {
    return Texture{"normal", 1, 1, {glm::vec4(glm::vec3(0.5 * n + 0.5), 1.0f)}};
}

// 8 x 1 heights rising by 1/8 a texel along u: a slope of 1 in texture units away from the
// wrap (between texel centres 1 and 6).
Texture rampAlongU() {
    Texture t{"ramp", 8, 1, {}};
    for (int x = 0; x < 8; ++x)
        t.texels.push_back(glm::vec4(glm::vec3(float(x) / 8.0f), 1.0f));
    return t;
}

Surface hitOf(const Scene &scene, Ray ray) {
    Hit hit;
    EXPECT_TRUE(traceClosest(scene, ray, kInf, hit));
    return surfaceAt(scene, ray, hit);
}

// A y-up plane's texture axes: u along n x x = -z, v along n x u = -x (planeUV).
TEST(SurfaceMaps, PlaneFrameFollowsItsTextureAxes) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.planes.push_back(Plane{{0, 0, 0}, {0, 1, 0}, 0});
    Surface s = hitOf(scene, Ray{{0.3, 2, 0.2}, {0, -1, 0}});
    TangentFrame f = tangentFrame(s.shadingNormal, s.dpdu, s.dpdv);
    expectNear(f.t, {0, 0, -1}, 1e-15);
    expectNear(f.b, {-1, 0, 0}, 1e-15);
    // A normal map leaning to +u: (0.6, 0, 0.8) in tangent space.
    scene.textures.push_back(normalTexel({0.6, 0.0, 0.8}));
    scene.materials[0].normalMap = 0;
    expectNear(mappedNormal(scene, s, scene.materials[0]), {0, 0.8, -0.6}, 1e-6);
}

// A sphere at its +x point: u turns towards +z (atan2(z, x)), v climbs towards +y.
TEST(SurfaceMaps, SphereFrameFollowsItsTextureCoordinates) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.spheres.push_back(Sphere{{0, 0, 0}, 1.0f, 0});
    Surface s = hitOf(scene, Ray{{5, 0, 0}, {-1, 0, 0}});
    TangentFrame f = tangentFrame(s.shadingNormal, s.dpdu, s.dpdv);
    expectNear(f.t, {0, 0, 1}, 1e-15);
    expectNear(f.b, {0, 1, 0}, 1e-15);
    scene.textures.push_back(normalTexel({0.0, 0.6, 0.8})); // leaning to +v: up
    scene.materials[0].normalMap = 0;
    expectNear(mappedNormal(scene, s, scene.materials[0]), {0.8, 0.6, 0}, 1e-6);
    // At the pole dp/du vanishes: the frame is the plane axes of +y, finite and orthonormal.
    Surface pole = hitOf(scene, Ray{{0, 5, 0}, {0, -1, 0}});
    TangentFrame p = tangentFrame(pole.shadingNormal, pole.dpdu, pole.dpdv);
    expectNear(p.t, {0, 0, -1}, 1e-12);
    expectNear(p.b, {-1, 0, 0}, 1e-12);
}

// dp/du and dp/dv from a triangle's UVs, with its v mirrored: b must follow +v, not n x t.
TEST(SurfaceMaps, TriangleFrameFromUVsKeepsMirroredLayouts) {
    Scene scene = test::sceneWithDefaultMaterial();
    test::addTriangle(scene, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 0); // faces +z
    TriangleShading &t = shadingFor(scene.triangles.back(), scene.triangleShading);
    t.hasUVs = true;
    t.uv[0] = {0, 1};
    t.uv[1] = {1, 1}; // u along +x
    t.uv[2] = {0, 0}; // v along -y: mirrored
    Surface s = hitOf(scene, Ray{{0.5, 0.5, 3}, {0, 0, -1}});
    TangentFrame f = tangentFrame(s.shadingNormal, s.dpdu, s.dpdv);
    expectNear(f.t, {1, 0, 0}, 1e-15);
    expectNear(f.b, {0, -1, 0}, 1e-15);
    // UVs without area (all corners alike): the fallback frame, no NaN.
    t.uv[1] = t.uv[2] = t.uv[0];
    Surface flat = hitOf(scene, Ray{{0.5, 0.5, 3}, {0, 0, -1}});
    TangentFrame g = tangentFrame(flat.shadingNormal, flat.dpdu, flat.dpdv);
    expectNear(g.t, {0, 1, 0}, 1e-15); // normalize(z x x)
    expectNear(g.b, {-1, 0, 0}, 1e-15);
}

// Blinn: heights rising along u lean the normal towards -u, by the slope times -bm.
TEST(SurfaceMaps, BumpSlopeLeansTheNormalAwayFromUphill) {
    Texture ramp = rampAlongU();
    glm::dvec2 slope = bumpSlope(ramp, {0.5, 0.5});
    EXPECT_NEAR(slope.x, 1.0, 1e-6);
    EXPECT_NEAR(slope.y, 0.0, 1e-12); // one row: nothing changes along v
    Scene scene = test::sceneWithDefaultMaterial();
    scene.planes.push_back(Plane{{0, 0, 0}, {0, 1, 0}, 0});
    scene.textures.push_back(ramp);
    scene.materials[0].bumpMap = 0;
    scene.materials[0].bumpScale = 0.5f;
    // u = -z, so z = -0.5 has u = 0.5; v = -x.
    Surface s = hitOf(scene, Ray{{-0.5, 2, -0.5}, {0, -1, 0}});
    EXPECT_NEAR(s.uv.x, 0.5, 1e-12);
    // Local (-0.5, 0, 1): -0.5 t + n = (0, 1, 0.5), normalised.
    expectNear(mappedNormal(scene, s, scene.materials[0]), glm::dvec3(0, 1, 0.5) / std::sqrt(1.25),
               1e-6);
    scene.materials[0].bumpScale = 0.0f; // no slope: the normal itself
    expectNear(mappedNormal(scene, s, scene.materials[0]), {0, 1, 0}, 1e-15);
}

} // namespace
} // namespace prism::reference
