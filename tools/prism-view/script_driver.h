#pragma once
// Runs a ViewScript through the viewer's hooks: the frame count, window resizes, a scene reload,
// the orbiting camera, RSS reports and the final screenshot that the tests and the soak run use.
#include <memory>

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

private:
    ViewScript script_;
    long startRssKiB_ = 0;
};

// The null driver for a user's session, a ScriptDriver when any hidden option was given.
std::unique_ptr<ViewDriver> makeViewDriver(const ViewScript &script);

} // namespace prism
