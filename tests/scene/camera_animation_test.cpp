// Camera animation (format 1.2): `key`, `turntable` and `interpolate` parse as documented, give
// the camera line at frame 1 to the bit, pass through every key, and reject what makes no sense
// with FILE:LINE (engine/scene/animation_directives.cpp, camera_animation.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "expect_file_error.h"
#include "scene/camera_animation.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"

namespace prism {
namespace {

using test::expectFileError;

constexpr const char *kFile = "anim.scene";
constexpr const char *kCamera = "camera eye 0 2 -8 look 0 1 0 fov 50\n";

void expectSameCamera(const Camera &a, const Camera &b) {
    EXPECT_EQ(a.eye, b.eye);
    EXPECT_EQ(a.look, b.look);
    EXPECT_EQ(a.up, b.up);
    EXPECT_EQ(a.fovDegrees, b.fovDegrees);
    EXPECT_EQ(a.orthoHeight, b.orthoHeight);
}

void expectError(const std::string &text, int line, const std::string &fragment) {
    SCOPED_TRACE(text);
    expectFileError([&] { parseScene(text, kFile); }, kFile, line, fragment);
}

TEST(CameraAnimation, AStillSceneHasOneCameraAtEveryFrame) {
    Scene scene = parseScene(std::string(kCamera) + "sphere 0 1 0 1\n", kFile);
    EXPECT_FALSE(scene.cameraAnimation.animated());
    for (double frame : {-3.0, 0.0, 1.0, 7.5, 240.0})
        expectSameCamera(cameraAt(scene, frame), scene.camera);
}

TEST(CameraAnimation, KeysChangeOnlyTheFieldsTheyName) {
    Scene scene = parseScene(std::string(kCamera) + "key 11 eye 10 2 -8\n"
                                                    "# keys may have comments between them\n"
                                                    "key 21 fov 30 look 0 0 0\n",
                             kFile);
    ASSERT_EQ(scene.cameraAnimation.keys.size(), 2u);
    const CameraKey &k1 = scene.cameraAnimation.keys[0], &k2 = scene.cameraAnimation.keys[1];
    EXPECT_EQ(k1.frame, 11.0);
    EXPECT_EQ(k1.line, 2);
    EXPECT_EQ(k1.camera.eye, glm::dvec3(10, 2, -8));
    EXPECT_EQ(k1.camera.look, glm::dvec3(0, 1, 0));
    EXPECT_EQ(k1.camera.fovDegrees, 50.0f);
    EXPECT_EQ(k2.camera.eye, glm::dvec3(10, 2, -8)); // held from the key before
    EXPECT_EQ(k2.camera.look, glm::dvec3(0, 0, 0));
    EXPECT_EQ(k2.camera.fovDegrees, 30.0f);
}

TEST(CameraAnimation, LinearKeysPassThroughEveryKeyAndHoldOutside) {
    Scene scene = parseScene(std::string(kCamera) + "key 11 eye 10 2 -8\nkey 21 fov 30\n", kFile);
    expectSameCamera(cameraAt(scene, 1.0), scene.camera);
    expectSameCamera(cameraAt(scene, -5.0), scene.camera);
    expectSameCamera(cameraAt(scene, 11.0), scene.cameraAnimation.keys[0].camera);
    expectSameCamera(cameraAt(scene, 21.0), scene.cameraAnimation.keys[1].camera);
    expectSameCamera(cameraAt(scene, 500.0), scene.cameraAnimation.keys[1].camera);
    Camera mid = cameraAt(scene, 6.0); // halfway from frame 1 to 11
    EXPECT_DOUBLE_EQ(mid.eye.x, 5.0);
    EXPECT_EQ(mid.fovDegrees, 50.0f);
    EXPECT_FLOAT_EQ(cameraAt(scene, 13.5).fovDegrees, 45.0f); // a quarter of 50 -> 30
}

TEST(CameraAnimation, CatmullRomIsSmoothThroughKeysAndExactAtThem) {
    std::string keys = "key 11 eye 10 2 -8\nkey 21 eye 10 2 2\nkey 41 eye 0 2 2\n";
    Scene spline = parseScene(std::string(kCamera) + keys + "interpolate catmull-rom\n", kFile);
    Scene linear = parseScene(std::string(kCamera) + keys, kFile);
    for (const CameraKey &k : spline.cameraAnimation.keys)
        expectSameCamera(cameraAt(spline, k.frame), k.camera);
    // At keys 11 and 21 the path turns corners; the spline rounds them (overshooting x = 10
    // between them), the straight lines do not.
    EXPECT_EQ(cameraAt(linear, 16.0).eye.x, 10.0);
    EXPECT_NEAR(cameraAt(spline, 16.0).eye.x, 10.0 + 0.625 + 10.0 / 24.0, 1e-12);
    // The velocity is continuous across a key: finite differences either side agree.
    auto z = [&](double f) { return cameraAt(spline, f).eye.z; };
    double h = 1e-4, before = (z(21.0) - z(21.0 - h)) / h, after = (z(21.0 + h) - z(21.0)) / h;
    EXPECT_NEAR(before, after, 1e-3 * std::abs(after) + 1e-6);
}

TEST(CameraAnimation, TurntableOrbitsTheLookPointAndClosesTheLoop) {
    Scene scene = parseScene(std::string(kCamera) + "turntable 24\n", kFile);
    ASSERT_TRUE(scene.cameraAnimation.turntable);
    expectSameCamera(cameraAt(scene, 1.0), scene.camera);
    expectSameCamera(cameraAt(scene, 25.0), scene.camera); // one whole turn: the same bits
    Camera quarter = cameraAt(scene, 7.0);                 // 90 degrees about +y
    EXPECT_NEAR(quarter.eye.x, -8.0, 1e-12);
    EXPECT_NEAR(quarter.eye.z, 0.0, 1e-12);
    EXPECT_NEAR(quarter.eye.y, 2.0, 1e-12);
    EXPECT_EQ(quarter.look, scene.camera.look); // the centre is the look point
    for (double f = 1.0; f <= 24.0; f += 1.0)   // the distance to the centre never changes
        EXPECT_NEAR(glm::length(cameraAt(scene, f).eye - scene.camera.look),
                    glm::length(scene.camera.eye - scene.camera.look), 1e-12);
    Scene half = parseScene(
        std::string(kCamera) + "turntable 10 center 0 0 0 axis 0 0 1 degrees 180\n", kFile);
    Camera ninety = cameraAt(half, 6.0); // 90 degrees about +z, the orbit's centre at 0
    EXPECT_NEAR(ninety.eye.x, -2.0, 1e-12);
    EXPECT_NEAR(ninety.eye.y, 0.0, 1e-12);
    EXPECT_NEAR(cameraAt(half, 11.0).eye.y, -2.0, 1e-12); // 180: the turn goes on past FRAMES
    EXPECT_NEAR(cameraAt(half, 21.0).eye.y, 2.0, 1e-12);  // 360
}

TEST(CameraAnimation, CentringMovesTheKeysWithTheScene) {
    Scene scene = parseScene(
        "camera eye 1000 2 -8 look 1000 1 0\nkey 11 eye 1010 2 -8\nsphere 1000 1 0 1\n", kFile);
    Camera before = cameraAt(scene, 11.0);
    centerOnCamera(scene);
    Camera after = cameraAt(scene, 11.0);
    EXPECT_EQ(after.eye, before.eye - glm::dvec3(1000, 2, -8));
    EXPECT_EQ(cameraAt(scene, 1.0).eye, glm::dvec3(0.0));
}

TEST(CameraAnimation, BadKeysAreErrorsAtTheirLine) {
    std::string c = kCamera;
    expectError("key 10 eye 1 2 3\n", 1, "'key' must follow the camera line");
    expectError(c + "sphere 0 0 0 1\nkey 10 eye 1 2 3\n", 3, "'key' must follow the camera line");
    expectError(c + "key 10 eye 1 2 3\nkey 5 eye 1 2 4\n", 3,
                "key frame 5 must come after the previous key's frame 10 (line 2): keys go in "
                "time order");
    expectError(c + "key 10 eye 1 2 3\nkey 10 eye 1 2 4\n", 3, "keys go in time order");
    expectError(c + "key 1 eye 1 2 3\n", 2, "must come after frame 1");
    expectError(c + "key 0.5 eye 1 2 3\n", 2, "must come after frame 1");
    expectError(c + "key 10 eye 0 1 0\n", 2, "key eye and look must differ");
    expectError(c + "key 10 up 0 0 0\n", 2, "key up 0 0 0 must not be zero");
    expectError(c + "key 10 fov 180\n", 2, "key fov must be between 0 and 180");
    expectError(c + "key 10 ortho 4\n", 2, "a key cannot change the projection");
    expectError("camera eye 0 0 5 look 0 0 0 ortho 4\nkey 10 fov 30\n", 2,
                "a key cannot change the projection");
    expectError(c + "key nan eye 1 2 3\n", 2, "nan");
    expectError(c + "key 10 eye 1 2\n", 2, "'eye' needs 3 values");
    expectError(c + "key 10 zoom 2\n", 2, "unknown key 'zoom'");
    expectError(c + "turntable 24\nkey 10 eye 1 2 3\n", 3, "'key' must follow the camera line");
}

TEST(CameraAnimation, BadTurntablesAndInterpolationsAreErrorsAtTheirLine) {
    std::string c = kCamera;
    expectError("turntable 24\n", 1, "must come above it");
    expectError(c + "turntable 0\n", 2, "turntable FRAMES must be > 0, got 0");
    expectError(c + "turntable -24\n", 2, "must be > 0");
    expectError(c + "turntable 24 axis 0 0 0\n", 2, "turntable axis must not be zero");
    expectError(c + "turntable 24\nturntable 12\n", 3, "only one turntable");
    expectError(c + "key 10 eye 1 2 3\nturntable 24\n", 3, "keys and a turntable exclude");
    expectError(c + "interpolate cubic\n", 2, "interpolate takes 'linear' or 'catmull-rom'");
    expectError(c + "interpolate linear\ninterpolate linear\n", 3, "only one interpolate");
}

TEST(CameraAnimation, ASplineThatOvershootsIntoNoViewIsAnErrorNamingTheFrameAndKeys) {
    // The look point sweeps through the eye's path: the straight line never meets the eye, but
    // here eye and look meet at frame 6 (both at x = 5).
    Scene scene = parseScene("camera eye 0 0 0 look 10 0 0\nkey 11 eye 10 0 0 look 0 0 0\n", kFile);
    try {
        cameraAt(scene, 6.0);
        ADD_FAILURE() << "no error";
    } catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("frame 6: the camera between the keys of the camera "
                                             "line and line 2 has no view"),
                  std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace prism
