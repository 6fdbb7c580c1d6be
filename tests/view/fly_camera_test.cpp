// The fly camera: untouched it is the scene's camera exactly (so a still viewer traces
// prism-render's rays), moves where it looks, never turns past the up axis.
#include <gtest/gtest.h>

#include "fly_camera.h"

namespace prism {
namespace {

Camera sceneCamera() {
    Camera c;
    c.eye = {0.3f, 2.6f, 7.6f};
    c.look = {0.3f, 0.9f, 0.0f};
    c.fovDegrees = 40.0f;
    return c;
}

TEST(FlyCamera, NoInputKeepsTheSceneCameraBitForBit) {
    FlyCamera fly(sceneCamera(), 2.0f);
    fly.update(FlyInput{}, 0.5);
    EXPECT_TRUE(sameCamera(fly.camera(), sceneCamera()));
}

TEST(FlyCamera, ForwardMovesAlongTheViewAtTheGivenSpeed) {
    FlyCamera fly(sceneCamera(), 2.0f);
    FlyInput input;
    input.move.z = 1.0f;
    fly.update(input, 0.5);
    glm::vec3 forward = glm::normalize(sceneCamera().look - sceneCamera().eye);
    glm::vec3 moved = fly.camera().eye - sceneCamera().eye;
    EXPECT_NEAR(glm::length(moved), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::normalize(moved), forward), 1.0f, 1e-5f);
    // The view direction is unchanged by moving.
    glm::vec3 view = glm::normalize(fly.camera().look - fly.camera().eye);
    EXPECT_NEAR(glm::dot(view, forward), 1.0f, 1e-5f);

    input.fast = true;
    FlyCamera fast(sceneCamera(), 2.0f);
    fast.update(input, 0.5);
    EXPECT_NEAR(glm::length(fast.camera().eye - sceneCamera().eye), FlyCamera::kFastFactor, 1e-4f);
}

TEST(FlyCamera, LookingUpStopsShortOfTheUpAxis) {
    FlyCamera fly(sceneCamera(), 1.0f);
    FlyInput input;
    input.turnPixels = {0.0f, -100000.0f}; // drag far up
    fly.update(input, 0.016);
    glm::vec3 view = glm::normalize(fly.camera().look - fly.camera().eye);
    EXPECT_NEAR(glm::degrees(std::acos(glm::dot(view, glm::vec3(0, 1, 0)))), 1.0f, 1e-2f);
}

TEST(FlyCamera, ScrollZoomsWithinLimitsAndResetRestores) {
    FlyCamera fly(sceneCamera(), 1.0f);
    FlyInput input;
    input.zoomSteps = 3.0f;
    fly.update(input, 0.016);
    EXPECT_FLOAT_EQ(fly.camera().fovDegrees, 34.0f);
    input.zoomSteps = 1000.0f;
    fly.update(input, 0.016);
    EXPECT_FLOAT_EQ(fly.camera().fovDegrees, 5.0f);
    fly.reset(sceneCamera());
    EXPECT_TRUE(sameCamera(fly.camera(), sceneCamera()));
}

} // namespace
} // namespace prism
