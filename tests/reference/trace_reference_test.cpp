// Shading of the reference against hand-computed values: Blinn-Phong, shadows, mirrors, glass.
#include <cmath>
#include <limits>
#include <utility>

#include <gtest/gtest.h>

#include "expect_near.h"
#include "reference/reference_renderer.h"
#include "reference/trace_reference.h"
#include "scene_builders.h"

namespace prism {
namespace {

using test::expectNear;

// One sphere at the origin, radius 1, lit by one point light; camera on +z.
Scene litSphere() {
    Scene scene = test::sceneWithDefaultMaterial();
    Material m;
    m.name = "orange";
    m.color = {0.8f, 0.4f, 0.2f};
    m.ambient = 0.15f;
    m.diffuse = 0.7f;
    m.specular = 0.5f;
    m.shininess = 20.0f;
    uint32_t id = test::addMaterial(scene, m);
    scene.spheres.push_back(Sphere{{0, 0, 0}, 1.0f, id});
    scene.lights.push_back(Light{{4, 5, 6}, {1.0f, 0.9f, 0.7f}, 0.0f});
    scene.ambient = {0.9f, 1.0f, 0.8f};
    scene.background = {0.0f, 0.0f, 0.3f};
    scene.camera.eye = {0, 0, 5};
    scene.camera.look = {0, 0, 0};
    scene.camera.fovDegrees = 40.0f;
    return scene;
}

struct Expected {
    glm::dvec3 ambientOnly, lit;
};

// The spec's shading formula, written out: the hit by the textbook quadratic, N = P for the unit
// sphere at the origin.
Expected blinnPhongByHand(const Scene &scene, int w, int h, int i, int j) {
    const Camera &cam = scene.camera;
    glm::dvec3 eye(cam.eye), forward = glm::normalize(glm::dvec3(cam.look) - eye);
    glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(cam.up)));
    glm::dvec3 up = glm::cross(right, forward);
    double hh = std::tan(glm::radians(double(cam.fovDegrees)) / 2), a = double(w) / h;
    double u = (i + 0.5) / w, v = (j + 0.5) / h;
    glm::dvec3 d = glm::normalize(forward + (2 * u - 1) * hh * a * right + (1 - 2 * v) * hh * up);
    double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1.0;
    double t = -b - std::sqrt(b * b - c);
    glm::dvec3 p = eye + t * d, n = glm::normalize(p);
    const Material &m = scene.materials[scene.spheres[0].material];
    glm::dvec3 color(m.color);
    glm::dvec3 ambient = double(m.ambient) * color * glm::dvec3(scene.ambient);
    const Light &light = scene.lights[0];
    glm::dvec3 l = glm::normalize(glm::dvec3(light.position) - p), hv = glm::normalize(l - d);
    glm::dvec3 lit =
        ambient + glm::dvec3(light.color) *
                      (double(m.diffuse) * color * std::max(0.0, glm::dot(n, l)) +
                       double(m.specular) * std::pow(std::max(0.0, glm::dot(n, hv)), m.shininess));
    return {ambient, lit};
}

RenderedImage render(const Scene &scene, int w, int h, uint32_t spp = 1, uint32_t depth = 5) {
    RenderSettings settings;
    settings.width = w;
    settings.height = h;
    settings.samplesPerPixel = spp;
    settings.maxDepth = depth;
    return renderReference(scene, settings);
}

glm::dvec3 pixel(const RenderedImage &image, int i, int j) {
    return glm::dvec3(image.rgba[size_t(j) * size_t(image.width) + size_t(i)]);
}

TEST(Shading, BlinnPhongMatchesTheHandComputedFormula) {
    Scene scene = litSphere();
    const int w = 21, h = 21;
    RenderedImage image = render(scene, w, h);
    for (auto [i, j] : {std::pair{10, 10}, {13, 7}, {12, 9}, {8, 11}}) {
        SCOPED_TRACE(testing::Message() << "pixel " << i << "," << j);
        Expected e = blinnPhongByHand(scene, w, h, i, j);
        ASSERT_GT(glm::length(e.lit - e.ambientOnly), 0.05) << "the light must reach it";
        expectNear(pixel(image, i, j), e.lit, 1e-6);
    }
    expectNear(pixel(image, 0, 0), glm::dvec3(scene.background), 0.0, "corner misses");
}

TEST(Shading, OccluderLeavesAmbientOnly) {
    Scene scene = litSphere();
    // The centre pixel sees (0, 0, 1); block the segment from there to the light.
    glm::dvec3 p(0, 0, 1), light(scene.lights[0].position);
    scene.spheres.push_back(Sphere{glm::vec3(p + 0.5 * (light - p)), 0.3f, 0});
    RayCounts rays;
    CameraFrame frame = makeCameraFrame(scene.camera, 21, 21);
    glm::dvec3 value = tracePixelSample(scene, frame, 10, 10, 0, 1, 5, rays);
    expectNear(value, blinnPhongByHand(scene, 21, 21, 10, 10).ambientOnly, 1e-12);
    EXPECT_EQ(rays.primary, 1u);
    EXPECT_EQ(rays.shadow, 1u) << "the blocked shadow ray is traced and counted";
    EXPECT_EQ(rays.secondary, 0u);
}

TEST(Shading, LightBehindTheSurfaceTracesNoShadowRay) {
    Scene scene = litSphere();
    scene.lights[0].position = {0, 0, -10};
    RayCounts rays;
    CameraFrame frame = makeCameraFrame(scene.camera, 21, 21);
    glm::dvec3 value = tracePixelSample(scene, frame, 10, 10, 0, 1, 5, rays);
    expectNear(value, blinnPhongByHand(scene, 21, 21, 10, 10).ambientOnly, 1e-12);
    EXPECT_EQ(rays.shadow, 0u);
}

// An ortho camera looks straight down -z at a mirror plane; reflected rays go back up +z.
// A red that shines by its ambient term alone: what a mirror shows of it is its colour times
// the scene's ambient, whatever the lights.
uint32_t addSelfLitRed(Scene &scene) {
    Material red;
    red.name = "red";
    red.color = {1.0f, 0.0f, 0.0f};
    red.ambient = 1.0f;
    red.diffuse = 0.0f;
    return test::addMaterial(scene, red);
}

Scene mirrorScene(float reflect) {
    Scene scene = test::sceneWithDefaultMaterial();
    Material mirror = test::opticalMaterial("mirror", reflect, 0.0f);
    mirror.ambient = 0.2f;
    mirror.color = {0.5f, 1.0f, 0.25f};
    uint32_t id = test::addMaterial(scene, mirror);
    scene.planes.push_back(Plane{{0, 0, 0}, {0, 0, 1}, id});
    scene.background = {0.2f, 0.5f, 0.9f};
    scene.camera.eye = {0, 0, 5};
    scene.camera.look = {0, 0, 0};
    scene.camera.orthoHeight = 2.0f;
    return scene;
}

TEST(Shading, MirrorReflectsTheBackground) {
    glm::dvec3 background(0.2f, 0.5f, 0.9f),
        ambient(0.2 * glm::dvec3(glm::vec3(0.5f, 1.0f, 0.25f)));
    RenderedImage image = render(mirrorScene(1.0f), 4, 4);
    expectNear(pixel(image, 1, 2), ambient + background, 1e-7);
    image = render(mirrorScene(0.5f), 4, 4);
    expectNear(pixel(image, 3, 0), ambient + 0.5 * background, 1e-7);
    image = render(mirrorScene(1.0f), 4, 4, 1, 1);
    expectNear(pixel(image, 1, 2), ambient, 1e-7, "depth 1: no reflected ray");
}

TEST(Shading, MirrorShowsWhatIsBehindTheCamera) {
    Scene scene = mirrorScene(1.0f);
    scene.materials[1].ambient = 0.0f;
    uint32_t id = addSelfLitRed(scene);
    scene.spheres.push_back(Sphere{{0, 0, 30}, 10.0f, id}); // behind the camera
    scene.ambient = {0.5f, 0.5f, 0.5f};
    RenderedImage image = render(scene, 4, 4);
    expectNear(pixel(image, 2, 1), {0.5, 0.0, 0.0}, 1e-7);
}

// A glass sphere (no surface colour of its own) in front of a coloured background.
Scene glassSphere(float ior = 1.5f, float transmit = 1.0f) {
    Scene scene = test::sceneWithDefaultMaterial();
    uint32_t glass = test::addMaterial(scene, test::opticalMaterial("glass", 0.0f, transmit, ior));
    scene.spheres.push_back(Sphere{{0, 0, 0}, 1.0f, glass});
    scene.background = {0.3f, 0.6f, 0.9f};
    scene.camera.eye = {0, 0, 5};
    scene.camera.look = {0, 0, 0};
    return scene;
}

// Head-on through the centre: every interface reflects F0 = 0.04 and transmits 0.96.
TEST(Shading, GlassAtNormalIncidenceSplitsBySchlick) {
    Scene scene = glassSphere();
    glm::dvec3 bg(scene.background);
    CameraFrame frame = makeCameraFrame(scene.camera, 9, 9);
    RayCounts rays;
    // Depth 2: the reflection goes back to the background, the refracted ray dies inside.
    expectNear(tracePixelSample(scene, frame, 4, 4, 0, 1, 2, rays), 0.04 * bg, 1e-7);
    EXPECT_EQ(rays.secondary, 2u);
    // Depth 3: the refracted ray also leaves through the back.
    rays = {};
    expectNear(tracePixelSample(scene, frame, 4, 4, 0, 1, 3, rays), (0.04 + 0.96 * 0.96) * bg,
               1e-7);
    EXPECT_EQ(rays.secondary, 4u);
}

// Off the axis each interface reflects Schlick's F = F0 + (1 - F0) (1 - cos)^5: at normal
// incidence the exponent does not matter, so the angles here are oblique to grazing (at
// sin = 0.95 an exponent of 4 reflects 0.22 instead of 0.19).
TEST(Shading, GlassAtObliqueAnglesFollowsSchlick) {
    Scene scene = glassSphere();
    glm::dvec3 bg(scene.background);
    for (double h : {0.5, 0.8, 0.95}) {
        SCOPED_TRACE(testing::Message() << "height " << h);
        // Depth 2: the reflection leaves to the background, the refracted ray ends inside.
        RayCounts rays;
        glm::dvec3 value =
            reference::traceRadiance(scene, {{0.0, h, 5.0}, {0.0, 0.0, -1.0}}, {0, 0}, 2, rays);
        double cosI = std::sqrt(1.0 - h * h);
        double fresnel = 0.04 + 0.96 * std::pow(1.0 - cosI, 5.0);
        expectNear(value, fresnel * bg, 1e-12);
        EXPECT_EQ(rays.secondary, 2u);
    }
}

// A ray inside a glass sphere meeting its surface at sin(theta) = 0.9 > 1 / 1.5 is totally
// reflected, and the reflection meets the surface at the same angle again: every hit pushes one
// ray with weight * transmit, nothing reaches the background.
TEST(Shading, GlassTotalInternalReflection) {
    Scene scene = glassSphere(1.5f, 0.5f);
    scene.materials[1].ambient = 1.0f; // each hit adds weight * 1
    scene.ambient = {1.0f, 1.0f, 1.0f};
    Ray inside{{0.0, 0.9, 0.0}, {1.0, 0.0, 0.0}};
    RayCounts rays;
    glm::dvec3 value = reference::traceRadiance(scene, inside, {0, 0}, 4, rays);
    expectNear(value, glm::dvec3(1.0 + 0.5 + 0.25 + 0.125), 1e-12);
    EXPECT_EQ(rays.secondary, 3u);

    // Below the critical angle it refracts out and the background shows.
    scene.materials[1].ambient = 0.0f;
    rays = {};
    value = reference::traceRadiance(scene, {{0.0, 0.5, 0.0}, {1.0, 0.0, 0.0}}, {0, 0}, 2, rays);
    EXPECT_GT(value.b, 0.1);
    EXPECT_EQ(rays.secondary, 2u) << "reflected and refracted";
}

// A triangle in z = 0 whose vertex normals all lean towards +x: shading must use that normal,
// not the triangle's own (0, 0, 1). Seen straight down -z at its centre.
Scene leaningTriangle(const Material &m) {
    Scene scene = test::sceneWithDefaultMaterial();
    uint32_t id = test::addMaterial(scene, m);
    test::addTriangle(scene, {-2, -2, 0}, {2, -2, 0}, {0, 2, 0}, id);
    TriangleShading &t = shadingFor(scene.triangles[0], scene.triangleShading);
    t.hasNormals = true;
    t.n[0] = t.n[1] = t.n[2] = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
    scene.background = {0.0f, 0.0f, 0.0f};
    return scene;
}

TEST(Shading, SmoothTriangleIsLitByItsInterpolatedNormal) {
    Material m;
    m.name = "matte";
    m.color = {1.0f, 1.0f, 1.0f};
    m.ambient = 0.0f;
    m.diffuse = 0.8f;
    Scene scene = leaningTriangle(m);
    scene.lights.push_back(Light{{3, 0, 3}, {1, 1, 1}, 0.0f});
    RayCounts rays;
    glm::dvec3 value =
        reference::traceRadiance(scene, {{0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}}, {0, 0}, 1, rays);
    glm::dvec3 n = glm::normalize(glm::dvec3(glm::vec3(scene.shadingOf(0).n[0])));
    double nDotL = glm::dot(n, glm::normalize(glm::dvec3(3, 0, 3))); // 0.88; (0, 0, 1) gives 0.71
    expectNear(value, glm::dvec3(double(m.diffuse) * nDotL), 1e-12);
}

TEST(Shading, SmoothMirrorReflectsAboutItsInterpolatedNormal) {
    Scene scene = leaningTriangle(test::opticalMaterial("mirror", 1.0f, 0.0f));
    glm::dvec3 n = glm::normalize(glm::dvec3(glm::vec3(scene.shadingOf(0).n[0])));
    glm::dvec3 mirrored = glm::reflect(glm::dvec3(0, 0, -1), n);
    // A self-lit red sphere where the mirrored ray goes (the flat normal sends it back up +z).
    uint32_t id = addSelfLitRed(scene);
    scene.spheres.push_back(Sphere{5.0 * mirrored, 1.0f, id});
    RayCounts rays;
    glm::dvec3 value =
        reference::traceRadiance(scene, {{0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}}, {0, 0}, 2, rays);
    expectNear(value, {1.0, 0.0, 0.0}, 1e-12);
}

// A spherical light partly hidden behind an occluder gives a wider partial shadow than a point
// light (whose only partial pixels are those the shadow edge crosses).
TEST(Shading, AreaLightGivesPenumbra) {
    Scene scene = test::sceneWithDefaultMaterial();
    scene.planes.push_back(Plane{{0, 0, 0}, {0, 1, 0}, 0});
    scene.spheres.push_back(Sphere{{0, 2, 0}, 1.0f, 0});
    scene.lights.push_back(Light{{0, 6, 0}, {1, 1, 1}, 0.0f});
    scene.camera.eye = {0, 10, 0};
    scene.camera.look = {0, 0, 0};
    scene.camera.up = {0, 0, -1};
    scene.camera.orthoHeight = 6.0f;
    const int size = 24;
    RenderedImage hard = render(scene, size, size, 16, 1);
    scene.lights[0].radius = 1.5f;
    RenderedImage soft = render(scene, size, size, 16, 1);
    scene.spheres.clear();
    RenderedImage lit = render(scene, size, size, 16, 1);
    const double ambient = 0.1 * double(0.8f);
    int softPartial = 0, hardPartial = 0;
    for (size_t p = 0; p < soft.rgba.size(); ++p) {
        if (lit.depth[p] != soft.depth[p])
            continue; // the occluder hides the floor here
        double full = lit.rgba[p].g - ambient;
        ASSERT_GT(full, 1e-3);
        double softVisible = (soft.rgba[p].g - ambient) / full;
        double hardVisible = (hard.rgba[p].g - ambient) / full;
        EXPECT_GE(softVisible, -1e-6);
        EXPECT_LE(softVisible, 1.0 + 1e-6);
        softPartial += softVisible > 0.05 && softVisible < 0.95;
        hardPartial += hardVisible > 0.05 && hardVisible < 0.95;
    }
    EXPECT_GT(softPartial, 2 * hardPartial);
}

} // namespace
} // namespace prism
