#pragma once
// The seam between the viewer's frame loop and what drives it besides a user: hooks the loop
// calls at fixed points of every frame, and the controls a driver may use from them. Keeping
// the tests' scripting behind it leaves the loop as a user runs it.
#include <cstdint>
#include <filesystem>

#include "feature_toggles.h"
#include "scene/scene.h"

namespace prism {

// What a driver may do to the viewer: what a user does with the window and keys, and what it
// needs to know to decide that it is done.
class ViewControls {
public:
    virtual void requestWindowSize(uint32_t width, uint32_t height) = 0;
    // The scene file becomes `path` and is reloaded, as if it had been edited: a broken one
    // shows its error, keeps the last good scene and returns false.
    virtual bool reloadSceneFrom(const std::filesystem::path &path) = 0;
    // The scene file shown (the command line's, or the last reloadSceneFrom's).
    virtual const std::filesystem::path &scenePath() const = 0;
    // The scene's camera, in the shown coordinates: centred, with this origin in the file's
    // coordinates (scene/scene_origin.h). A file edit adds the origin back.
    virtual const Camera &sceneCamera() const = 0;
    virtual glm::dvec3 sceneOrigin() const = 0;
    virtual void placeCamera(const Camera &camera) = 0;
    // As the overlay's checkboxes do: rebuilds the tracer. On failure (the message is shown)
    // the previous features stay and this returns false.
    virtual bool setFeatures(const FeatureToggles &features) = 0;
    virtual const FeatureToggles &features() const = 0;
    // `base`'s .exr and .png, as F12 writes them.
    virtual void saveScreenshot(const std::filesystem::path &base) = 0;
    // All --spp samples are in and no swapchain rebuild is pending.
    virtual bool converged() const = 0;
    virtual uint32_t samplesTarget() const = 0;
    // Vulkan validation messages so far (0 without --validation).
    virtual uint32_t validationMessages() const = 0;

protected:
    ~ViewControls() = default; // not owned through this interface
};

// The hooks, in the order the loop calls them. This base class is the null driver of a user's
// session: every hook does nothing.
class ViewDriver {
public:
    virtual ~ViewDriver() = default;

    // True: there is no user. Input, key handling and file watching are off, and input() below
    // stands in for them.
    virtual bool scripted() const { return false; }
    virtual void begin() {}
    // At the start of frame `frame`, before the loop reads the window's size.
    virtual void beforeFrame(uint32_t /*frame*/, ViewControls & /*view*/) {}
    // Where a user's keys and scene edits are handled, in runs without a user (scripted or
    // --benchmark, whose camera path then overrides any camera placed here).
    virtual void input(uint32_t /*frame*/, ViewControls & /*view*/) {}
    virtual void swapchainRebuilt(uint32_t /*width*/, uint32_t /*height*/) {}
    // Frame `frame` has been submitted.
    virtual void afterFrame(uint32_t /*frame*/) {}
    // After `frames` frames: true ends the loop. Not asked in --benchmark runs, which end with
    // their path.
    virtual bool done(uint32_t /*frames*/, const ViewControls & /*view*/) { return false; }
    // The loop has ended and the device is idle.
    virtual void end(uint32_t /*frames*/, ViewControls & /*view*/) {}
};

} // namespace prism
