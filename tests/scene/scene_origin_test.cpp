// Camera-relative coordinates (scene/scene_origin.h): the move is exact in double, the
// rounding to float happens once and from the file's coordinates.
#include <cfloat>

#include <gtest/gtest.h>

#include "scene/scene_origin.h"
#include "scene/scene_parser.h"

namespace prism {
namespace {

Scene farScene() {
    return parseScene("camera eye 1000000.25 2 3 look 1000000.25 2 0\n"
                      "light 1000010.5 5 5\n"
                      "sphere 1000000.3 2 -1 0.5\n"
                      "plane 0 -1 0 0 1 0\n"
                      "triangle 1000001 0 0 1000002 0 0 1000001 1 0\n"
                      "triangle 1000000.3 2.3 3.3 1000002 0 0 1000001 1 0\n",
                      "far.scene");
}

TEST(SceneOrigin, PositionsKeepTheirDecimalsFarFromTheOrigin) {
    Scene scene = farScene();
    EXPECT_EQ(scene.spheres[0].center.x, 1000000.3); // a float would hold 1000000.3125
    EXPECT_EQ(scene.camera.eye.x, 1000000.25);
}

TEST(SceneOrigin, MoveOriginShiftsEveryPositionAndRemembersWhere) {
    Scene scene = farScene();
    moveOrigin(scene, scene.camera.eye); // the scene's own eye: taken by value, not aliased
    EXPECT_EQ(scene.origin, glm::dvec3(1000000.25, 2, 3));
    EXPECT_EQ(scene.camera.eye, glm::dvec3(0.0));
    EXPECT_EQ(scene.camera.look, glm::dvec3(0, 0, -3));
    EXPECT_EQ(scene.lights[0].position, glm::dvec3(10.25, 3, 2));
    EXPECT_NEAR(scene.spheres[0].center.x, 0.05, 1e-9);
    EXPECT_EQ(scene.planes[0].point, glm::dvec3(-1000000.25, -3, -3));
    EXPECT_EQ(scene.triangles[0].p[1], glm::dvec3(1.75, -2, -3));
    EXPECT_EQ(scene.spheres[0].radius, 0.5f); // lengths and directions do not move
    EXPECT_EQ(scene.planes[0].normal, glm::vec3(0, 1, 0));
    moveOrigin(scene, glm::dvec3(1, 0, 0));
    EXPECT_EQ(scene.origin, glm::dvec3(1000001.25, 2, 3));
    EXPECT_EQ(scene.triangles[0].p[1], glm::dvec3(0.75, -2, -3));
}

TEST(SceneOrigin, CentringRoundsToTheFloatsTheGpuIsGiven) {
    Scene scene = farScene();
    centerOnCamera(scene);
    double x = scene.spheres[0].center.x; // 0.05 in double, rounded to float once
    EXPECT_EQ(x, double(float(x)));
    EXPECT_NEAR(x, 0.05, 1e-8); // a float at 1e6 would be 0.0625 off
    EXPECT_EQ(scene.origin, glm::dvec3(1000000.25, 2, 3));
    // Each of a vertex's three components (GCC 12 once rounded only z of each: scene_origin.cpp),
    // against constants: 0.0499999999302 and 0.2999999999999998 in double, these floats after.
    EXPECT_EQ(scene.triangles[1].p[0], glm::dvec3(0.05f, 0.3f, 0.3f));
    EXPECT_EQ(scene.triangles[1].p[1], glm::dvec3(1.75, -2, -3));
}

TEST(SceneOrigin, RecentringOnlyWhenFloatsGetCoarseForTheView) {
    // Floats at distance r are up to r * FLT_EPSILON apart; the bound is 1e-5 view distances.
    double atLimit = 1e-5 * 4.0 / double(FLT_EPSILON); // ~335 for a view distance of 4
    EXPECT_FALSE(needsRecentering(glm::dvec3(0.0), 4.0));
    EXPECT_FALSE(needsRecentering(glm::dvec3(0.9 * atLimit, 0, 0), 4.0));
    EXPECT_TRUE(needsRecentering(glm::dvec3(0, 1.1 * atLimit, 0), 4.0));
    EXPECT_TRUE(needsRecentering(glm::dvec3(1e6, 0, 0), 1000.0));
}

} // namespace
} // namespace prism
