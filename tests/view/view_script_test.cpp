// The hidden options of scripted runs and the driver that runs them, without a window: a fake
// viewer records what the driver asks of it, frame by frame.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "benchmark.h"
#include "core/error.h"
#include "fake_view.h"
#include "fly_camera.h"
#include "script_driver.h"
#include "view_options.h"

namespace prism {
namespace {

// parseViewOptions on a prism-view command line; `args` follow the program name.
bool parseCommandLine(std::vector<std::string> args, ViewOptions &options, ViewScript &script,
                      int &exitCode) {
    args.insert(args.begin(), "prism-view");
    std::vector<char *> argv;
    for (std::string &arg : args)
        argv.push_back(arg.data());
    return parseViewOptions(int(argv.size()), argv.data(), options, script, exitCode);
}

ViewScript parseScript(std::vector<std::string> args, ViewOptions *optionsOut = nullptr) {
    ViewOptions options;
    ViewScript script;
    int exitCode = 0;
    EXPECT_TRUE(parseCommandLine(std::move(args), options, script, exitCode));
    if (optionsOut)
        *optionsOut = options;
    return script;
}

using test::FakeView;

TEST(ViewScript, HiddenOptionsParseIntoTheScriptNotTheUserOptions) {
    ViewOptions options;
    ViewScript script =
        parseScript({"s.scene", "--size", "320x240", "--script-frames", "10", "--resize-at",
                     "3:200x150", "--resize-at", "6:320x240", "--script-reload", "4:b.scene",
                     "--screenshot", "out.exr", "--script-orbit", "--report-every", "250"},
                    &options);
    EXPECT_EQ(options.width, 320u);
    EXPECT_EQ(script.frames, 10u);
    ASSERT_EQ(script.resizes.size(), 2u);
    EXPECT_EQ(script.resizes[0].frame, 3u);
    EXPECT_EQ(script.resizes[0].width, 200u);
    EXPECT_EQ(script.resizes[0].height, 150u);
    EXPECT_EQ(script.resizes[1].frame, 6u);
    EXPECT_EQ(script.reloadFrame, 4u);
    EXPECT_EQ(script.reloadPath, "b.scene");
    EXPECT_EQ(script.screenshotPath, "out.exr");
    EXPECT_TRUE(script.orbit);
    EXPECT_EQ(script.reportEvery, 250u);
    EXPECT_FALSE(script.empty());
    EXPECT_TRUE(parseScript({"s.scene"}).empty());
}

TEST(ViewScript, SoakOptionsParse) {
    ViewScript script = parseScript({"s.scene", "--script-seconds", "600", "--script-reload-every",
                                     "80", "--script-toggle-every", "30", "--script-resize-every",
                                     "60:400x300,256x192,320x240"});
    EXPECT_DOUBLE_EQ(script.seconds, 600.0);
    EXPECT_EQ(script.frames, 0u);
    EXPECT_TRUE(script.scripted()) << "a time limit alone ends the run";
    EXPECT_EQ(script.reloadEvery, 80u);
    EXPECT_EQ(script.toggleEvery, 30u);
    EXPECT_EQ(script.resizeEvery, 60u);
    ASSERT_EQ(script.resizeCycle.size(), 3u);
    EXPECT_EQ(script.resizeCycle[0].width, 400u);
    EXPECT_EQ(script.resizeCycle[1].height, 192u);
    EXPECT_EQ(script.resizeCycle[2].width, 320u);
    EXPECT_FALSE(script.empty());
    EXPECT_DOUBLE_EQ(parseScript({"s.scene", "--script-seconds", "0.5"}).seconds, 0.5);
    EXPECT_EQ(parseScript({"s.scene", "--script-frames", "9", "--script-resize-every", "5:64x48"})
                  .resizeCycle.size(),
              1u);
}

// The message of the prism::Error that parsing `args` throws ("" if none).
// A malformed option is a usage error (tools/common/command_line.h): parsing stops with exit
// status 2 and the message on stderr, which this returns.
std::string parseError(std::vector<std::string> args) {
    ViewOptions options;
    ViewScript script;
    int exitCode = 0;
    ::testing::internal::CaptureStderr();
    bool goOn = parseCommandLine(std::move(args), options, script, exitCode);
    std::string message = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(goOn);
    EXPECT_EQ(exitCode, 2);
    EXPECT_EQ(message.rfind("prism-view: error: ", 0), 0u) << message;
    return message;
}

// CLI11 rejects a value its check refuses: parsing stops with the usage status, 2.
int cliExitCode(std::vector<std::string> args) {
    ViewOptions options;
    ViewScript script;
    int exitCode = 0;
    EXPECT_FALSE(parseCommandLine(std::move(args), options, script, exitCode));
    return exitCode;
}

TEST(ViewScript, MalformedHiddenOptionsSayWhatIsWrong) {
    EXPECT_NE(parseError({"s.scene", "--resize-at", "3x200"}).find("--resize-at"),
              std::string::npos);
    EXPECT_NE(parseError({"s.scene", "--script-reload", "b.scene"}).find("--script-reload"),
              std::string::npos);
    EXPECT_NE(parseError({"s.scene", "--screenshot", "out.exr"}).find("--screenshot"),
              std::string::npos);

    const std::vector<std::string> run = {"s.scene", "--script-frames", "10"};
    auto with = [&](std::vector<std::string> more) {
        more.insert(more.begin(), run.begin(), run.end());
        return parseError(more);
    };
    for (const char *bad : {"50", "50:", "x:320x240", "50:320x", "50:320x240,", "50:320x240;64x48"})
        EXPECT_NE(with({"--script-resize-every", bad}).find("--script-resize-every"),
                  std::string::npos)
            << bad;
    EXPECT_NE(with({"--script-resize-every", "50"}).find("N:WxH[,WxH...]"), std::string::npos);
    EXPECT_NE(with({"--script-resize-every", "0:320x240"}).find("N >= 1"), std::string::npos);
    EXPECT_NE(with({"--script-reload-every", "5", "--script-reload", "3:b.scene"})
                  .find("cannot be combined with --script-reload"),
              std::string::npos);
    // Without an end there is no script to run them.
    for (const char *option :
         {"--script-reload-every", "--script-toggle-every", "--script-fly-away"})
        EXPECT_NE(
            parseError({"s.scene", option, "5"}).find("--script-frames N or --script-seconds S"),
            std::string::npos)
            << option;
    EXPECT_NE(parseError({"s.scene", "--script-resize-every", "5:64x48"}).find("--script-seconds"),
              std::string::npos);

    EXPECT_EQ(cliExitCode({"s.scene", "--script-seconds", "0"}), 2);
    EXPECT_EQ(cliExitCode({"s.scene", "--script-seconds", "-1"}), 2);
    EXPECT_EQ(cliExitCode({"s.scene", "--script-seconds", "ten"}), 2);
    EXPECT_EQ(cliExitCode({"s.scene", "--script-frames", "9", "--script-toggle-every", "0"}), 2);
    EXPECT_EQ(cliExitCode({"s.scene", "--script-frames", "9", "--script-reload-every", "-3"}), 2);
}

TEST(ScriptDriver, AUserSessionGetsTheNullDriver) {
    std::unique_ptr<ViewDriver> driver = makeViewDriver(ViewScript{});
    EXPECT_EQ(dynamic_cast<ScriptDriver *>(driver.get()), nullptr);
    EXPECT_FALSE(driver->scripted());
    ViewScript reportOnly;
    reportOnly.reportEvery = 10; // RSS reports also work in a user's session
    driver = makeViewDriver(reportOnly);
    EXPECT_NE(dynamic_cast<ScriptDriver *>(driver.get()), nullptr);
    EXPECT_FALSE(driver->scripted());
}

TEST(ScriptDriver, ResizesAndReloadsAtTheirFrames) {
    ViewScript script;
    script.frames = 10;
    script.resizes = {{3, 200, 150}, {6, 320, 240}};
    script.reloadFrame = 4;
    script.reloadPath = "b.scene";
    ScriptDriver driver(script);
    FakeView view;
    EXPECT_TRUE(driver.scripted());
    for (uint32_t frame = 0; frame < 10; ++frame) {
        driver.beforeFrame(frame, view);
        driver.input(frame, view);
        if (frame == 3) {
            EXPECT_EQ(view.resizes, std::vector<std::string>{"200x150"});
        }
        EXPECT_EQ(view.reloads.size(), frame < 4 ? 0u : 1u) << "frame " << frame;
    }
    EXPECT_EQ(view.resizes, (std::vector<std::string>{"200x150", "320x240"}));
    EXPECT_EQ(view.reloads, std::vector<std::filesystem::path>{"b.scene"});
    EXPECT_TRUE(view.placed.empty()) << "without --script-orbit the scene's camera is held";
}

TEST(ScriptDriver, OrbitPlacesTheBenchmarkPathEveryFrame) {
    ViewScript script;
    script.frames = 300;
    script.orbit = true;
    ScriptDriver driver(script);
    FakeView view;
    view.scene.eye = {0.0f, 2.0f, 8.0f};
    view.scene.look = {0.0f, 1.0f, 0.0f};
    for (uint32_t frame = 0; frame < 250; ++frame)
        driver.input(frame, view);
    ASSERT_EQ(view.placed.size(), 250u);
    EXPECT_TRUE(sameCamera(view.placed[7], benchmarkCamera(view.scene, 7, 240)));
    EXPECT_TRUE(sameCamera(view.placed[245], benchmarkCamera(view.scene, 5, 240)));
}

// The far-from-the-origin test jumps 1000 view distances back along the view, then returns to
// the scene's camera as the view then gives it (re-centred by the jump).
TEST(ScriptDriver, FlyAwayJumpsBackAndReturns) {
    ViewScript script;
    script.frames = 5;
    script.flyAwayFrame = 2;
    ScriptDriver driver(script);
    FakeView view;
    view.scene.eye = {0.0, 0.0, 4.0};
    view.scene.look = {0.0, 0.0, 0.0};
    for (uint32_t frame = 0; frame < 5; ++frame)
        driver.input(frame, view);
    ASSERT_EQ(view.placed.size(), 2u);
    EXPECT_EQ(view.placed[0].eye, glm::dvec3(0.0, 0.0, 4004.0));
    EXPECT_EQ(view.placed[0].look, glm::dvec3(0.0, 0.0, 4000.0));
    EXPECT_TRUE(sameCamera(view.placed[1], view.scene));
}

TEST(ScriptDriver, EndsAfterItsFramesAndWaitsForAConvergedScreenshot) {
    ViewScript plain;
    plain.frames = 6;
    ScriptDriver run(plain);
    FakeView view;
    EXPECT_FALSE(run.done(5, view));
    EXPECT_TRUE(run.done(6, view)) << "no screenshot: convergence does not matter";

    ViewScript shot = plain;
    shot.screenshotPath = "out.exr";
    ScriptDriver driver(shot);
    EXPECT_FALSE(driver.done(6, view));
    view.isConverged = true;
    EXPECT_TRUE(driver.done(7, view));
    driver.end(7, view);
    EXPECT_EQ(view.screenshots, std::vector<std::filesystem::path>{"out.exr"});

    // Not forever: frames + 2 * spp + 120.
    view.isConverged = false;
    EXPECT_FALSE(driver.done(6 + 2 * 4 + 119, view));
    EXPECT_THROW(driver.done(6 + 2 * 4 + 120, view), Error);
}

} // namespace
} // namespace prism
