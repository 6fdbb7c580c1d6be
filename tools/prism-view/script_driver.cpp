#include "script_driver.h"

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>
#include <utility>

#include "benchmark.h"
#include "core/error.h"

namespace prism {
namespace {

// The soak run's orbit: the benchmark path, repeated every this many frames.
constexpr uint32_t kOrbitFrames = 240;

// Resident set size in KiB, from /proc (the soak run watches it).
long residentKiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

} // namespace

ScriptDriver::ScriptDriver(ViewScript script) : script_(std::move(script)) {}

bool ScriptDriver::scripted() const {
    return script_.frames > 0;
}

void ScriptDriver::begin() {
    if (script_.reportEvery > 0)
        startRssKiB_ = residentKiB(); // the baseline: after start-up, before the first frame
}

void ScriptDriver::beforeFrame(uint32_t frame, ViewControls &view) {
    for (const ScriptedResize &resize : script_.resizes)
        if (resize.frame == frame)
            view.requestWindowSize(resize.width, resize.height);
}

void ScriptDriver::input(uint32_t frame, ViewControls &view) {
    if (!script_.reloadPath.empty() && frame == script_.reloadFrame)
        view.reloadSceneFrom(script_.reloadPath);
    // The soak run moves every frame; the image tests hold the scene's camera.
    if (script_.orbit)
        view.placeCamera(benchmarkCamera(view.sceneCamera(), frame % kOrbitFrames, kOrbitFrames));
}

void ScriptDriver::swapchainRebuilt(uint32_t width, uint32_t height) {
    if (scripted()) // the image test checks that its resizes happened
        std::fprintf(stderr, "prism-view: swapchain %ux%u\n", width, height);
}

void ScriptDriver::afterFrame(uint32_t frame) {
    if (script_.reportEvery > 0 && frame % script_.reportEvery == 0)
        std::fprintf(stderr, "prism-view: frame %u rss_kib %ld\n", frame, residentKiB());
}

bool ScriptDriver::done(uint32_t frames, const ViewControls &view) {
    if (!scripted() || frames < script_.frames)
        return false;
    // A screenshot waits for a converged accumulation (a resize late in the script restarts
    // it), but not forever.
    if (script_.screenshotPath.empty() || view.converged())
        return true;
    uint32_t patience = script_.frames + 2 * view.samplesTarget() + 120;
    if (frames >= patience)
        throw Error("the scripted run did not converge to " + std::to_string(view.samplesTarget()) +
                    " samples in " + std::to_string(frames) + " frames");
    return false;
}

void ScriptDriver::end(uint32_t frames, ViewControls &view) {
    if (!script_.screenshotPath.empty())
        view.saveScreenshot(script_.screenshotPath);
    if (script_.reportEvery > 0)
        std::fprintf(stderr, "prism-view: frames %u rss_kib start %ld end %ld\n", frames,
                     startRssKiB_, residentKiB());
}

std::unique_ptr<ViewDriver> makeViewDriver(const ViewScript &script) {
    if (script.empty())
        return std::make_unique<ViewDriver>();
    return std::make_unique<ScriptDriver>(script);
}

} // namespace prism
