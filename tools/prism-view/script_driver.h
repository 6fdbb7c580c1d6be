#pragma once
// Runs a ViewScript through the viewer's hooks: the frame count or time limit, window resizes,
// scene reloads, feature toggles, the orbiting camera, RSS reports and the final screenshot
// that the tests and the soak run use.
#include <memory>
#include <string>

#include "core/timer.h"
#include "soak_report.h"
#include "view_driver.h"
#include "view_script.h"

namespace prism {

class ScriptDriver final : public ViewDriver {
public:
    explicit ScriptDriver(ViewScript script);

    bool scripted() const override;
    void begin() override;
    void beforeFrame(uint32_t frame, ViewControls &view) override;
    void input(uint32_t frame, ViewControls &view) override;
    void swapchainRebuilt(uint32_t width, uint32_t height) override;
    void afterFrame(uint32_t frame) override;
    // Throws prism::Error when a run with a screenshot does not converge in good time.
    bool done(uint32_t frames, const ViewControls &view) override;
    void end(uint32_t frames, ViewControls &view) override;

    // What has been counted so far; complete after end().
    const SoakReport &report() const { return report_; }

private:
    void editScene(uint32_t edit, ViewControls &view);
    void toggleFeature(uint32_t step, ViewControls &view);
    void periodEnded(uint32_t frames);
    bool warmedUp(uint32_t frames) const;

    ViewScript script_;
    Timer clock_; // since begin()
    SoakReport report_;
    // The scene file's text before the first edit, restored at the end.
    std::string originalScene_;
    Camera editCamera_; // the scene's camera at the first edit: every variant places alike
    bool edited_ = false;
    FeatureToggles wanted_; // the features the toggle walk has reached
    bool toggled_ = false;
};

// The null driver for a user's session, a ScriptDriver when any hidden option was given.
std::unique_ptr<ViewDriver> makeViewDriver(const ViewScript &script);

// The period of a soak run's script, in frames: the least common multiple of the periods of
// its orbit, resizes, scene edits and feature toggles (1 when it has none). From one period on,
// every frame's window size, scene, features and camera are those of the frame one period
// earlier, so each period end finds the viewer in the same state: memory that grows from one
// period end to the next is a leak, not a first-time allocation (a pipeline variant, an image
// size, a scene size, a shader compile).
uint32_t soakPeriodFrames(const ViewScript &script);

} // namespace prism
