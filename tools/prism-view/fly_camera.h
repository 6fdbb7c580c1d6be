#pragma once
// A fly camera over the scene's camera model: move along the view (WASD) and the scene's up
// axis (QE), turn by dragging, zoom by changing the field of view. Until it is first moved it
// is bit for bit the scene's camera, so a still viewer traces exactly prism-render's rays.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

struct FlyInput {
    glm::vec3 move{0.0f};       // x: right, y: up, z: forward; each -1, 0 or 1
    bool fast = false;          // Shift
    glm::vec2 turnPixels{0.0f}; // mouse drag since the last update (x right, y down)
    float zoomSteps = 0.0f;     // scroll wheel notches, positive = zoom in
};

class FlyCamera {
public:
    // `unitsPerSecond`: walking speed, chosen from the scene's size.
    FlyCamera(const Camera &start, float unitsPerSecond);
    void reset(const Camera &start);
    void update(const FlyInput &input, double seconds);
    const Camera &camera() const { return camera_; }

    static constexpr float kDegreesPerPixel = 0.15f;
    static constexpr float kFastFactor = 5.0f;

private:
    Camera camera_;
    float unitsPerSecond_;
};

// A walking speed that crosses the scene in a few seconds.
float flySpeedFor(const Scene &scene, const glm::vec3 &boundsMin, const glm::vec3 &boundsMax);

// Two cameras trace the same rays only when every field is equal.
bool sameCamera(const Camera &a, const Camera &b);

} // namespace prism
