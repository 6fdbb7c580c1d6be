// The soak run's script without a window: the time limit, the periodic resizes, scene edits
// and feature toggles, the period they imply, the warm-up and the summary line soak.sh reads.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "fake_view.h"
#include "scene/scene_loader.h"
#include "scene_edit.h"
#include "script_driver.h"

namespace prism {
namespace {

namespace fs = std::filesystem;
using test::FakeView;

std::string readText(const fs::path &path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs frames [0, count) through the hooks the loop calls.
void runFrames(ScriptDriver &driver, FakeView &view, uint32_t count) {
    for (uint32_t frame = 0; frame < count; ++frame) {
        driver.beforeFrame(frame, view);
        driver.input(frame, view);
        driver.afterFrame(frame);
    }
}

TEST(SoakScript, ATimeLimitEndsTheRunAfterItsFramesToo) {
    ViewScript script;
    script.seconds = 0.05;
    script.frames = 3;
    ScriptDriver driver(script);
    FakeView view;
    EXPECT_TRUE(driver.scripted());
    driver.begin();
    EXPECT_FALSE(driver.done(100, view)) << "50 ms have not passed";
    std::this_thread::sleep_for(std::chrono::milliseconds(80));
    EXPECT_FALSE(driver.done(2, view)) << "--script-frames is still a minimum";
    EXPECT_TRUE(driver.done(3, view));
}

TEST(SoakScript, ResizesCycleThroughTheirSizes) {
    ViewScript script;
    script.frames = 100;
    script.resizeEvery = 10;
    script.resizeCycle = {{400, 300}, {256, 192}, {320, 240}};
    ScriptDriver driver(script);
    FakeView view;
    runFrames(driver, view, 71); // events at frames 10, 20, ..., 70
    EXPECT_EQ(view.resizes, (std::vector<std::string>{"400x300", "256x192", "320x240", "400x300",
                                                      "256x192", "320x240", "400x300"}));
    EXPECT_EQ(driver.report().resizes, 7u);
}

TEST(SoakScript, TheToggleWalkFlipsOneFeatureAtATimeAndComesBack) {
    ViewScript script;
    script.frames = 100;
    script.toggleEvery = 5;
    ScriptDriver driver(script);
    FakeView view;
    view.current.grid = false; // as with --grid off: the walk starts from there
    FeatureToggles start = view.current;
    runFrames(driver, view, 41); // steps at frames 5, 10, ..., 40
    ASSERT_EQ(view.featureChanges.size(), 8u);
    const FeatureToggles &first = view.featureChanges[0];
    EXPECT_FALSE(first.shadows);
    EXPECT_TRUE(first.reflection && first.refraction && !first.grid);
    const FeatureToggles &fourth = view.featureChanges[3];
    EXPECT_TRUE(!fourth.shadows && !fourth.reflection && !fourth.refraction && fourth.grid);
    for (size_t i = 0; i + 1 < view.featureChanges.size(); ++i)
        EXPECT_FALSE(view.featureChanges[i] == start) << "step " << i + 1;
    EXPECT_TRUE(view.featureChanges[7] == start) << "8 steps flip every feature twice";
    EXPECT_EQ(driver.report().toggles, 8u);
    EXPECT_EQ(driver.report().errors, 0u);

    FakeView failing;
    failing.featuresSucceed = false;
    ScriptDriver again(script);
    runFrames(again, failing, 11);
    EXPECT_EQ(again.report().errors, 2u) << "a failed rebuild is an error of the run";
}

class SoakSceneEdits : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("prism-soak-test-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(SoakSceneEdits, VariantsAddSpheresAndParse) {
    const std::string text = "camera eye 0 0 5 look 0 0 0\nlight 2 2 5\nsphere 0 0 0 1";
    Camera camera;
    EXPECT_EQ(sceneVariant(text, camera, 0), text);
    EXPECT_EQ(sceneVariant(text, camera, kSceneVariants), text) << "the variants cycle";
    for (uint32_t variant = 1; variant < kSceneVariants; ++variant) {
        Scene scene = parseScene(sceneVariant(text, camera, variant), dir_ / "s.scene");
        ASSERT_EQ(scene.spheres.size(), 1u + variant) << variant;
        EXPECT_EQ(scene.spheres.back().material, 0u) << "the built-in default material";
        EXPECT_NEAR(scene.spheres.back().radius, 0.2f, 1e-6f); // 4% of the distance 5
        // Beside the look point, in front of the camera.
        EXPECT_NEAR(glm::length(scene.spheres.back().center - camera.look), 1.25f, 1e-5f);
    }
}

TEST_F(SoakSceneEdits, EditsRewriteTheSceneFileAndEndRestoresIt) {
    const std::string text = "camera eye 0 0 5 look 0 0 0\nlight 2 2 5\nsphere 0 0 0 1\n";
    fs::path scene = dir_ / "s.scene";
    std::ofstream(scene) << text;
    ViewScript script;
    script.frames = 100;
    script.reloadEvery = 10;
    ScriptDriver driver(script);
    FakeView view;
    view.path = scene;
    runFrames(driver, view, 11);
    EXPECT_EQ(readText(scene), sceneVariant(text, view.scene, 1));
    runFrames(driver, view, 21); // frames 0-20 again: edits 1 and 2
    EXPECT_EQ(readText(scene), sceneVariant(text, view.scene, 2));
    runFrames(driver, view, 31);
    EXPECT_EQ(readText(scene), text) << "edit 3 is variant 0";
    EXPECT_EQ(view.reloads.size(), 6u);
    EXPECT_EQ(view.reloads.front(), scene);
    EXPECT_EQ(driver.report().reloads, 6u);
    runFrames(driver, view, 11);
    driver.end(11, view);
    EXPECT_EQ(readText(scene), text) << "the file ends as it started";

    view.reloadSucceeds = false;
    ScriptDriver failing(script);
    runFrames(failing, view, 11);
    EXPECT_EQ(failing.report().errors, 1u);
}

TEST(SoakScript, ThePeriodIsOneCycleOfEverythingPeriodic) {
    ViewScript script;
    script.seconds = 60;
    EXPECT_EQ(soakPeriodFrames(script), 1u) << "nothing periodic: every frame is alike";
    script.toggleEvery = 30; // 8 steps: 240
    EXPECT_EQ(soakPeriodFrames(script), 240u);
    script.reloadEvery = 80; // 3 variants: 240
    script.resizeEvery = 60;
    script.resizeCycle = {{400, 300}, {256, 192}, {480, 270}, {320, 240}}; // 240
    script.orbit = true;                                                   // 240
    EXPECT_EQ(soakPeriodFrames(script), 240u) << "the soak script's periods line up";
    script.reloadEvery = 50; // 150: lcm(240, 150) = 1200
    EXPECT_EQ(soakPeriodFrames(script), 1200u);
}

TEST(SoakScript, TheSummaryLineCountsTheRun) {
    ViewScript script;
    script.frames = 100;
    script.reportEvery = 10;
    script.toggleEvery = 2; // a period of 16 frames
    ScriptDriver driver(script);
    FakeView view;
    view.messages = 3;
    driver.begin();
    runFrames(driver, view, 100);
    driver.swapchainRebuilt(64, 48);
    driver.end(100, view);
    const SoakReport &r = driver.report();
    EXPECT_EQ(r.frames, 100u);
    EXPECT_EQ(r.periodFrames, 16u);
    EXPECT_EQ(r.warmupFrames, 32u) << "the first period end after 20% of the frames";
    EXPECT_EQ(r.toggles, 49u);
    EXPECT_EQ(r.swapchainRebuilds, 1u);
    EXPECT_EQ(r.validationMessages, 3u);
    EXPECT_GT(r.rssStartKiB, 0);
    EXPECT_GT(r.rssWarmKiB, 0);
    EXPECT_GT(r.rssEndKiB, 0) << "period ends at 48, 64, 80 and 96 came after the warm-up";
    EXPECT_GT(r.rssExitKiB, 0);
    EXPECT_GE(r.rssPeakKiB, std::max({r.rssWarmKiB, r.rssEndKiB, r.rssExitKiB}));
    std::string line = soakSummaryLine(r);
    for (const char *key :
         {"prism-view: soak ", "frames=100 ", "swapchain_rebuilds=1 ", "toggles=49 ", "errors=0 ",
          "period_frames=16 ", "warmup_frames=32 ", "rss_kib_start=", "rss_kib_warm=",
          "rss_kib_end=", "rss_kib_peak=", "rss_kib_exit=", "validation_messages=3"})
        EXPECT_NE(line.find(key), std::string::npos) << key << " in " << line;
}

TEST(SoakScript, ARunTooShortForItsWarmUpSaysSo) {
    ViewScript script;
    script.frames = 100;
    script.reportEvery = 50;
    script.toggleEvery = 2;
    FakeView view;
    ScriptDriver tooShort(script);
    tooShort.begin();
    runFrames(tooShort, view, 20);
    tooShort.end(20, view);
    EXPECT_EQ(tooShort.report().warmupFrames, 0u);
    EXPECT_EQ(tooShort.report().rssWarmKiB, -1) << "the run ended before its warm-up did";
    EXPECT_EQ(tooShort.report().rssEndKiB, -1);

    ScriptDriver noSecondEnd(script);
    noSecondEnd.begin();
    runFrames(noSecondEnd, view, 40);
    noSecondEnd.end(40, view);
    EXPECT_EQ(noSecondEnd.report().warmupFrames, 32u);
    EXPECT_EQ(noSecondEnd.report().rssEndKiB, -1) << "no period end after the warm-up's";

    ViewScript timed;
    timed.seconds = 60;
    timed.reportEvery = 50;
    timed.toggleEvery = 2;
    ScriptDriver early(timed);
    early.begin();
    runFrames(early, view, 200);
    EXPECT_EQ(early.report().warmupFrames, 0u) << "20% of 60 s have not passed";
}

} // namespace
} // namespace prism
