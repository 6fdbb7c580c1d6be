// Refraction held to Snell's law, not to the other renderer: a glass plane between the camera
// and the gradient sky (gradient_sky.h), so that the radiance of the centre pixel names the
// elevation of the refracted and reflected rays. Both renderers must give the hand-computed
// value: sin(theta_t) = eta sin(theta_i) with eta = 1 / ior entering (the ray against the plane's
// normal) and ior leaving, the Fresnel weight by Schlick's approximation at the incident angle
// (f0 = ((ior - 1) / (ior + 1))^2), and total internal reflection, where eta sin(theta_i) > 1,
// sending all of the transmitted weight along the mirror direction.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "gradient_sky.h"
#include "render_helpers.h"
#include "scene_builders.h"

namespace prism::test {
namespace {

class Refraction : public GpuTest {};

constexpr double kIor = 1.5;

// A camera at the origin looking along (0, +-cos theta_i, -sin theta_i) at a glass plane of
// normal +y one unit above or below it: going down, the ray enters the glass; going up, it hits
// the plane's back and leaves.
struct Setup {
    double incidence; // theta_i, radians from the normal
    bool fromAbove;
};

Scene glassPlaneScene(const Setup &s) {
    Scene scene = sceneWithDefaultMaterial();
    addGradientSky(scene);
    uint32_t glass = addMaterial(scene, opticalMaterial("glass", 0.0f, 1.0f, float(kIor)));
    scene.planes.push_back(
        Plane{{0.0, s.fromAbove ? -1.0 : 1.0, 0.0}, {0.0f, 1.0f, 0.0f}, glass});
    double vertical = s.fromAbove ? -std::cos(s.incidence) : std::cos(s.incidence);
    // Up along -z: never parallel to the view, straight down included.
    scene.camera = cameraAlong({0.0, vertical, -std::sin(s.incidence)}, {0.0f, 0.0f, -1.0f});
    return scene;
}

// What the centre pixel must read in the sky's red channel, computed by hand, with `sky` giving
// the sky's red along a direction.
template <typename Sky> double expectedRed(const Setup &s, Sky sky) {
    double cosI = std::cos(s.incidence), sinI = std::sin(s.incidence);
    double towardsPlane = s.fromAbove ? -1.0 : 1.0; // the ray's vertical direction
    // The mirror direction turns the vertical component over; the horizontal one stays.
    double reflected = sky(glm::dvec3(0.0, -towardsPlane * cosI, -sinI));
    double eta = s.fromAbove ? 1.0 / kIor : kIor;
    double sinT = eta * sinI;
    if (sinT > 1.0)
        return reflected; // total internal reflection: all of it along the mirror direction
    double cosT = std::sqrt(1.0 - sinT * sinT);
    double refracted = sky(glm::dvec3(0.0, towardsPlane * cosT, -sinT));
    double f0 = (kIor - 1.0) / (kIor + 1.0);
    f0 *= f0;
    double fresnel = f0 + (1.0 - f0) * std::pow(1.0 - cosI, 5.0);
    return fresnel * reflected + (1.0 - fresnel) * refracted;
}

constexpr size_t kCentre = 4 * (4 * 9 + 4); // the centre pixel of a 9x9 image

// The sky as the shader sees it along `dir`: a camera looking that way, no glass. The shader's
// asin is Vulkan's (within 4096 ulps, about 1.5e-4 of v; Environment.RowsFollowTheElevation
// holds it to that), so the glass pixel is held to the shader's own sky along the hand-computed
// directions: what remains is the refraction's own error.
double gpuSky(vk::Context &context, glm::dvec3 dir) {
    Scene scene = sceneWithDefaultMaterial();
    addGradientSky(scene);
    scene.camera = cameraAlong(dir, {0.0f, 0.0f, -1.0f});
    return renderGpu(context, scene, 9, 9, 1, 1).image.rgba[kCentre];
}

void expectSnell(vk::Context &context, const Setup &s) {
    SCOPED_TRACE(std::string(s.fromAbove ? "entering" : "leaving") + " at " +
                 std::to_string(s.incidence) + " rad");
    Scene scene = glassPlaneScene(s);
    // Depth 2: the camera ray, then the refracted and reflected rays that reach the sky.
    std::vector<float> gpu = renderGpu(context, scene, 9, 9, 1, 2).image.rgba;
    std::vector<float> cpu = renderCpu(scene, 9, 9, 1, 2);
    // The reference: double throughout, stored as float.
    EXPECT_NEAR(cpu[kCentre], expectedRed(s, gradientSkyRed), 1e-6);
    // The shader: 2e-5 for float's rounding of the angles' sines and the Fresnel weight. A
    // refracted ray off by a thousandth of a radian moves the sky's v by about 3e-4.
    double gpuWant = expectedRed(s, [&](glm::dvec3 dir) { return gpuSky(context, dir); });
    EXPECT_NEAR(gpu[kCentre], gpuWant, 2e-5);
}

TEST_F(Refraction, EnteringBendsTowardsTheNormal) {
    for (double degrees : {0.0, 20.0, 45.0, 70.0})
        expectSnell(context(), {degrees * kPi / 180.0, true});
}

TEST_F(Refraction, LeavingBendsAwayFromTheNormal) {
    // Up to the critical angle, asin(1 / 1.5) = 41.8 degrees.
    for (double degrees : {0.0, 15.0, 30.0, 40.0})
        expectSnell(context(), {degrees * kPi / 180.0, false});
}

TEST_F(Refraction, PastTheCriticalAngleAllIsReflected) {
    for (double degrees : {43.0, 55.0, 75.0})
        expectSnell(context(), {degrees * kPi / 180.0, false});
}

} // namespace
} // namespace prism::test
