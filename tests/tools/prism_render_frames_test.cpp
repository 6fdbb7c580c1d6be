// prism-render --frames (issue 32): a range of an animated scene's frames in one process, each
// the same image as a render of that frame alone, written under a pattern's names; resumable
// with --skip-existing; bad ranges and patterns refused before any work.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "io/image_reader.h"
#include "temp_dir_fixture.h"

namespace fs = std::filesystem;

namespace {

using prism::test::CliResult;

CliResult run(const std::string &args) {
    return prism::test::runTool(PRISM_RENDER_EXE, args);
}

// Two spheres on a floor, the camera orbiting them in six frames: each frame a new view.
constexpr const char *kTurntable = "camera eye 0 1.5 -5 look 0 0.5 0 fov 45\n"
                                   "turntable 6\n"
                                   "light 3 5 -4 radius 0.3\n"
                                   "material red color 0.9 0.2 0.1 specular 0.5\n"
                                   "plane 0 0 0 0 1 0\n"
                                   "sphere -0.8 0.6 0 0.6 red\n"
                                   "sphere 0.9 0.4 0.5 0.4\n";

class PrismRenderFrames : public prism::test::TempDirTest {
protected:
    std::string scene() { return write("turntable.scene", kTurntable).string(); }
    // prism-render on the turntable at 32x24 with 4 samples (soft shadows, jittered pixels).
    CliResult render(const std::string &args) {
        return run(scene() + " --size 32x24 --spp 4 --depth 3 --quiet " + args);
    }
    std::vector<float> pixels(const std::string &name) {
        return prism::readImage(dir() / name).pixels;
    }
};

TEST_F(PrismRenderFrames, EachFrameOfARangeIsTheImageOfThatFrameAlone) {
    CliResult range = render("--frames 1-6 --stats -o " + (dir() / "t.####.exr").string());
    ASSERT_EQ(range.exitCode, 0) << range.out;
    for (int f = 1; f <= 6; ++f)
        EXPECT_TRUE(fs::exists(dir() / ("t.000" + std::to_string(f) + ".exr"))) << f;
    ASSERT_EQ(render("--frames 4 -o " + (dir() / "alone4.exr").string()).exitCode, 0);
    ASSERT_EQ(render("-o " + (dir() / "still.exr").string()).exitCode, 0);
    EXPECT_EQ(pixels("alone4.exr"), pixels("t.0004.exr")) << "frame 4 alone and in the range";
    EXPECT_EQ(pixels("still.exr"), pixels("t.0001.exr")) << "the still is frame 1";
    EXPECT_NE(pixels("t.0001.exr"), pixels("t.0004.exr")) << "the camera moved";
    // A whole turn later the camera is back where it started, to the bit.
    ASSERT_EQ(render("--frames 7 -o " + (dir() / "turned.exr").string()).exitCode, 0);
    EXPECT_EQ(pixels("turned.exr"), pixels("t.0001.exr"));

    prism::LoadedImage four = prism::readImage(dir() / "t.0004.exr");
    auto frame = std::find_if(four.metadata.ints.begin(), four.metadata.ints.end(),
                              [](const auto &kv) { return kv.first == "prism:frame"; });
    ASSERT_NE(frame, four.metadata.ints.end());
    EXPECT_EQ(frame->second, 4);

    nlohmann::json stats = nlohmann::json::parse(range.stdoutOnly);
    ASSERT_EQ(stats["per_frame"].size(), 6u);
    EXPECT_EQ(stats["frames"].get<int>(), 6);
    EXPECT_EQ(stats["skipped"].get<int>(), 0);
    for (size_t i = 0; i < 6; ++i) {
        const nlohmann::json &f = stats["per_frame"][i];
        EXPECT_EQ(f["frame"].get<int>(), int(i) + 1);
        EXPECT_GT(f["trace_ms"].get<double>(), 0.0);
        EXPECT_GT(f["write_ms"].get<double>(), 0.0);
        EXPECT_GE(f["frame_ms"].get<double>(), f["trace_ms"].get<double>() * 0.5);
    }
}

TEST_F(PrismRenderFrames, ListsStepsAndBracePatterns) {
    CliResult r = render("--frames 2,5-9:3 -o " + (dir() / "v_{frame}.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::vector<std::string> files = entries();
    std::sort(files.begin(), files.end());
    EXPECT_EQ(files, (std::vector<std::string>{"turntable.scene", "v_2.png", "v_5.png",
                                               "v_8.png"}));
}

TEST_F(PrismRenderFrames, SkipExistingFinishesAStoppedRange) {
    std::string out = " -o " + (dir() / "t.##.exr").string();
    ASSERT_EQ(render("--frames 1-3" + out).exitCode, 0);
    std::vector<float> three = pixels("t.03.exr");
    fs::remove(dir() / "t.02.exr"); // as if the range had stopped there
    CliResult resumed = render("--frames 1-4 --skip-existing --stats" + out);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.out;
    nlohmann::json stats = nlohmann::json::parse(resumed.stdoutOnly);
    EXPECT_EQ(stats["skipped"].get<int>(), 2);
    ASSERT_EQ(stats["per_frame"].size(), 2u);
    EXPECT_EQ(stats["per_frame"][0]["frame"].get<int>(), 2);
    EXPECT_EQ(stats["per_frame"][1]["frame"].get<int>(), 4);
    EXPECT_TRUE(fs::exists(dir() / "t.02.exr"));
    EXPECT_TRUE(fs::exists(dir() / "t.04.exr"));
    EXPECT_EQ(pixels("t.03.exr"), three) << "an existing frame is left alone";
    // Nothing left to do: a message, success, and no scene read (the scene is broken now).
    write("turntable.scene", "sphere 0 0 0 -1\n");
    CliResult done = run((dir() / "turntable.scene").string() + " --frames 1-4 --skip-existing" +
                         out);
    EXPECT_EQ(done.exitCode, 0) << done.out;
    EXPECT_NE(done.out.find("all 4 images exist already"), std::string::npos) << done.out;
}

TEST_F(PrismRenderFrames, BadRangesAndPatternsFailBeforeAnyWork) {
    std::string exr = " -o " + (dir() / "t.####.exr").string();
    struct Case {
        std::string args, message;
    };
    for (const Case &c : std::vector<Case>{
             {"--frames 240-1" + exr, "the range '240-1' runs backwards"},
             {"--frames ''" + exr, "the list is empty"},
             {"--frames 1-3:0" + exr, "must be >= 1"},
             {"--frames 1,1" + exr, "frame 1 is listed twice"},
             {"--frames x" + exr, "is not a frame"},
             {"--frames 1-3 -o " + (dir() / "t.exr").string(), "names no frame"},
             {"--frames 1-3 -o " + (dir() / "t.##.##.exr").string(), "two runs of '#'"},
             {"--frames 1-3 --runs 3" + exr, "--runs times one frame"},
         }) {
        CliResult r = render(c.args);
        EXPECT_NE(r.exitCode, 0) << c.args;
        EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << ": " << r.out;
    }
    EXPECT_EQ(entries().size(), 1u) << "only the scene: nothing written";
}

TEST_F(PrismRenderFrames, KeysOutOfTimeOrderAreAnErrorAtTheirLine) {
    fs::path bad = write("keys.scene", "camera eye 0 1 -5 look 0 0 0\n"
                                       "key 20 eye 5 1 0\n"
                                       "key 10 eye 0 1 5\n"
                                       "sphere 0 0 0 1\n");
    CliResult r = run(bad.string() + " --frames 1-20 --quiet -o " +
                      (dir() / "k.####.exr").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(bad.string() + ":3: key frame 10 must come after the previous key's "
                                        "frame 20 (line 2)"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(entries().size(), 1u);
}

// Two tetrahedra placed from one prototype over a floor; the first slides and turns over eight
// frames, the second holds still.
constexpr const char *kTetra =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
std::string movingScene(const std::string &firstPlace) {
    return "camera eye 0 1.5 -5 look 0 0.5 0 fov 45\n"
           "light 3 5 -4\n"
           "plane 0 0 0 0 1 0\n"
           "mesh tetra.obj as t\n" +
           firstPlace + "\nplace t translate 0.5 0 1\n";
}

TEST_F(PrismRenderFrames, MovingInstancesAreTheStillSceneAtTheirKeys) {
    write("tetra.obj", kTetra);
    fs::path moving = write("moving.scene", movingScene("place t rotate y 0 translate -1.5 0 0\n"
                                                        "key 9 rotate y 120 translate 0.8 0.2 -1"));
    fs::path still = write("still.scene", movingScene("place t rotate y 120 translate 0.8 0.2 -1"));
    std::string common = " --size 32x24 --spp 2 --depth 2 --grid regular --quiet ";
    CliResult range = run(moving.string() + common + "--frames 1-9:4 --stats -o " +
                          (dir() / "m.#.exr").string());
    ASSERT_EQ(range.exitCode, 0) << range.out;
    ASSERT_EQ(run(still.string() + common + "-o " + (dir() / "still.exr").string()).exitCode, 0);
    ASSERT_EQ(run(moving.string() + common + "--frames 5 -o " + (dir() / "alone5.exr").string())
                  .exitCode,
              0);
    EXPECT_EQ(pixels("m.9.exr"), pixels("still.exr")) << "frame 9 is the place line at key 9";
    EXPECT_EQ(pixels("m.5.exr"), pixels("alone5.exr")) << "frame 5 alone and in the range";
    EXPECT_NE(pixels("m.1.exr"), pixels("m.5.exr"));
    EXPECT_NE(pixels("m.5.exr"), pixels("m.9.exr"));
    nlohmann::json stats = nlohmann::json::parse(range.stdoutOnly);
    ASSERT_EQ(stats["per_frame"].size(), 3u);
    EXPECT_EQ(stats["per_frame"][0]["move_ms"].get<double>(), 0.0) << "frame 1 as loaded";
    EXPECT_GT(stats["per_frame"][1]["move_ms"].get<double>(), 0.0) << "moved: built, uploaded";

    // The CPU reference moves the instances too.
    std::string cpu = common + "--backend cpu ";
    ASSERT_EQ(run(moving.string() + cpu + "--frames 1-9:8 -o " + (dir() / "c.#.exr").string())
                  .exitCode,
              0);
    ASSERT_EQ(run(still.string() + cpu + "-o " + (dir() / "cstill.exr").string()).exitCode, 0);
    EXPECT_EQ(pixels("c.9.exr"), pixels("cstill.exr"));
    EXPECT_NE(pixels("c.1.exr"), pixels("c.9.exr"));
}

TEST_F(PrismRenderFrames, BadPlacementKeysAreAnErrorAtTheirLine) {
    write("tetra.obj", kTetra);
    fs::path bad = write("bad.scene", movingScene("place t rotate y 0\nkey 9 rotate x 40"));
    CliResult r = run(bad.string() + " --frames 1-9 --quiet -o " + (dir() / "b.#.exr").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(bad.string() + ":6: a key's rotations must be those of its place line "
                                        "(line 5), about y in that order; this key gives x"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(dir() / "b.1.exr"));

    // Good keys whose spline swings the scale below 0 at frame 4: the range fails before any
    // frame is written, naming the scene, the frame and the keys' lines.
    fs::path swing = write("swing.scene",
                           movingScene("place t scale 1\nkey 3 scale 0.02\nkey 30 scale 0.02\n"
                                       "key 31 scale 5\ninterpolate catmull-rom"));
    r = run(swing.string() + " --frames 1-12 --quiet -o " + (dir() / "s.#.exr").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(swing.string() + ": frame 4: the placement between the keys of line 6 "
                                          "and line 7 cannot be traced"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(dir() / "s.1.exr")) << "no frame of a range that cannot finish";
}

} // namespace
