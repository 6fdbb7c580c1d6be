#include "script_driver.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <sstream>
#include <utility>

#include "benchmark.h"
#include "core/error.h"
#include "scene_edit.h"

namespace prism {
namespace {

// The soak run's orbit: the benchmark path, repeated every this many frames.
constexpr uint32_t kOrbitFrames = 240;
// The toggle walk flips shadows, reflection, refraction, grid, then the same again: after 8
// steps every feature is back, having been off alone, with others, and all together.
constexpr uint32_t kToggleFeatures = 4;
constexpr uint32_t kToggleSteps = 2 * kToggleFeatures;

// Periodic event number k (1, 2, ...) happens at frame k * every.
bool eventAt(uint32_t frame, uint32_t every) {
    return every > 0 && frame > 0 && frame % every == 0;
}

std::string readFile(const std::filesystem::path &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("cannot read " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeFile(const std::filesystem::path &path, const std::string &text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out)
        throw Error("cannot write " + path.string());
}

} // namespace

uint32_t soakPeriodFrames(const ViewScript &script) {
    uint64_t period = 1;
    bool any = false;
    auto add = [&](uint64_t frames) {
        if (frames == 0)
            return;
        period = std::min<uint64_t>(std::lcm(period, frames), UINT32_MAX);
        any = true;
    };
    if (script.orbit)
        add(kOrbitFrames);
    add(uint64_t(script.resizeEvery) * script.resizeCycle.size());
    add(uint64_t(script.reloadEvery) * kSceneVariants);
    add(uint64_t(script.toggleEvery) * kToggleSteps);
    return any ? uint32_t(period) : 1; // nothing periodic: every frame is like the last
}

ScriptDriver::ScriptDriver(ViewScript script) : script_(std::move(script)) {
    report_.periodFrames = soakPeriodFrames(script_);
}

bool ScriptDriver::scripted() const {
    return script_.scripted();
}

void ScriptDriver::begin() {
    clock_.reset();
    if (script_.reportEvery > 0)
        report_.rssStartKiB = residentKiB(); // after start-up, before the first frame
}

void ScriptDriver::beforeFrame(uint32_t frame, ViewControls &view) {
    for (const ScriptedResize &resize : script_.resizes)
        if (resize.frame == frame)
            view.requestWindowSize(resize.width, resize.height);
    if (eventAt(frame, script_.resizeEvery)) {
        size_t k = frame / script_.resizeEvery; // 1, 2, ...: sizes 0, 1, ...
        const ImageSize &size = script_.resizeCycle[(k - 1) % script_.resizeCycle.size()];
        view.requestWindowSize(size.width, size.height);
        report_.resizes += 1;
    }
}

void ScriptDriver::input(uint32_t frame, ViewControls &view) {
    if (!script_.reloadPath.empty() && frame == script_.reloadFrame)
        view.reloadSceneFrom(script_.reloadPath);
    if (eventAt(frame, script_.reloadEvery))
        editScene(frame / script_.reloadEvery, view);
    if (eventAt(frame, script_.toggleEvery))
        toggleFeature(frame / script_.toggleEvery, view);
    if (script_.flyAwayFrame > 0 && frame == script_.flyAwayFrame) {
        Camera far = view.sceneCamera();
        glm::dvec3 back = far.eye - far.look;
        far.eye += 1000.0 * back;
        far.look += 1000.0 * back;
        view.placeCamera(far);
    } else if (script_.flyAwayFrame > 0 && frame == script_.flyAwayFrame + 1) {
        view.placeCamera(view.sceneCamera()); // in the coordinates of the far camera by now
    }
    // The soak run moves every frame; the image tests hold the scene's camera.
    if (script_.orbit)
        view.placeCamera(benchmarkCamera(view.sceneCamera(), frame % kOrbitFrames, kOrbitFrames));
}

void ScriptDriver::editScene(uint32_t edit, ViewControls &view) {
    if (!edited_) {
        originalScene_ = readFile(view.scenePath());
        editCamera_ = view.sceneCamera(); // in the file's coordinates: the edit goes there
        editCamera_.eye += view.sceneOrigin();
        editCamera_.look += view.sceneOrigin();
        edited_ = true;
    }
    // Written in place, as an editor saves, and reloaded as if the file watcher had seen it.
    writeFile(view.scenePath(), sceneVariant(originalScene_, editCamera_, edit % kSceneVariants));
    report_.reloads += 1;
    if (!view.reloadSceneFrom(view.scenePath()))
        report_.errors += 1;
}

void ScriptDriver::toggleFeature(uint32_t step, ViewControls &view) {
    if (!toggled_) {
        wanted_ = view.features(); // the walk starts from the command line's (e.g. --grid off)
        toggled_ = true;
    }
    bool *features[kToggleFeatures] = {&wanted_.shadows, &wanted_.reflection, &wanted_.refraction,
                                       &wanted_.grid};
    bool &feature = *features[(step - 1) % kToggleFeatures];
    feature = !feature;
    report_.toggles += 1;
    if (!view.setFeatures(wanted_))
        report_.errors += 1;
}

void ScriptDriver::swapchainRebuilt(uint32_t width, uint32_t height) {
    report_.swapchainRebuilds += 1;
    if (scripted()) // the image test checks that its resizes happened
        std::fprintf(stderr, "prism-view: swapchain %ux%u\n", width, height);
}

bool ScriptDriver::warmedUp(uint32_t frames) const {
    // One period meets every state once, but the allocators under the viewer (glibc's arenas,
    // lavapipe's and the validation layers' pools) keep settling for a while: in a 10-minute
    // soak RSS rose by 3% from the first period end to the third and was flat after. So the
    // warm-up is the first 20% of the run (and at least one period), which leaves 80% of it
    // for a leak to show.
    if (frames < report_.periodFrames || frames < script_.frames / 5)
        return false;
    return clock_.elapsedMs() >= script_.seconds * 1000.0 / 5;
}

void ScriptDriver::periodEnded(uint32_t frames) {
    long kib = residentKiB();
    if (report_.warmupFrames > 0) {
        report_.rssEndKiB = kib; // a later period end than the warm-up's
        report_.rssPeakKiB = std::max(report_.rssPeakKiB, kib);
    } else if (warmedUp(frames)) {
        report_.warmupFrames = frames;
        report_.rssWarmKiB = kib;
        report_.rssPeakKiB = kib;
    }
}

void ScriptDriver::afterFrame(uint32_t frame) {
    if (script_.reportEvery == 0)
        return;
    if ((frame + 1) % report_.periodFrames == 0)
        periodEnded(frame + 1);
    if (frame % script_.reportEvery == 0) {
        long kib = residentKiB();
        if (report_.warmupFrames > 0)
            report_.rssPeakKiB = std::max(report_.rssPeakKiB, kib);
        std::fprintf(stderr, "prism-view: frame %u seconds %.0f rss_kib %ld\n", frame,
                     clock_.elapsedMs() / 1000.0, kib);
    }
}

bool ScriptDriver::done(uint32_t frames, const ViewControls &view) {
    if (!scripted() || frames < script_.frames)
        return false;
    if (script_.seconds > 0.0 && clock_.elapsedMs() < script_.seconds * 1000.0)
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
    if (edited_) // the file ends as it started, whatever variant the last edit wrote
        writeFile(view.scenePath(), originalScene_);
    if (!script_.screenshotPath.empty())
        view.saveScreenshot(script_.screenshotPath);
    report_.frames = frames;
    report_.seconds = clock_.elapsedMs() / 1000.0;
    report_.validationMessages = view.validationMessages();
    if (script_.reportEvery > 0) {
        report_.rssExitKiB = residentKiB();
        if (report_.warmupFrames > 0)
            report_.rssPeakKiB = std::max(report_.rssPeakKiB, report_.rssExitKiB);
        std::fprintf(stderr, "%s\n", soakSummaryLine(report_).c_str());
    }
}

std::unique_ptr<ViewDriver> makeViewDriver(const ViewScript &script) {
    if (script.empty())
        return std::make_unique<ViewDriver>();
    return std::make_unique<ScriptDriver>(script);
}

} // namespace prism
