// prism-view as a user runs it, headless: under Xvfb with lavapipe and validation layers on (any
// message makes prism-view exit 1). A scripted run holds the scene's camera, resizes the window
// twice, then saves the converged accumulation; it must equal prism-render's image of the same
// scene, size and sample count, because both record the same tracer dispatches.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h" // tests/tools
#include "io/image_reader.h"
#include "missing_tool.h"
#include "wavy_field_obj.h"

namespace fs = std::filesystem;

namespace {

using prism::test::CliResult;

CliResult run(const std::string &command) {
    return prism::test::runTool(command, "");
}

bool haveXvfbRun() {
    return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

// -a picks a free display number; the screen is larger than any window the tests open.
// prism-view's own exit status is printed as a marker: xvfb-run replaces it with 5 when its
// temporary directory cannot be removed, which happens now and then on a busy machine.
std::string underXvfb(const std::string &args) {
    return "xvfb-run -a -s \"-screen 0 1024x768x24\" sh -c '" + std::string(PRISM_VIEW_EXE) + " " +
           args + "; echo prism-view-exit=$?'";
}

// The status prism-view exited with, from the marker above (-1 if it never got to print it).
int viewExit(const CliResult &r) {
    size_t at = r.out.rfind("prism-view-exit=");
    return at == std::string::npos ? -1 : std::atoi(r.out.c_str() + at + 16);
}

// The largest difference of any channel of any pixel (images of the same size).
double largestDifference(const prism::LoadedImage &a, const prism::LoadedImage &b) {
    double largest = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        largest = std::max(largest, double(std::abs(a.pixels[i] - b.pixels[i])));
    return largest;
}

class PrismViewXvfb : public ::testing::Test {
protected:
    void SetUp() override {
        if (!haveXvfbRun())
            PRISM_MISSING_TEST_TOOL("xvfb-run is not installed (Debian: apt install xvfb)");
        dir_ = fs::temp_directory_path() /
               ("prism-view-test-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        if (!dir_.empty())
            fs::remove_all(dir_);
    }
    fs::path write(const std::string &name, const std::string &text) {
        std::ofstream(dir_ / name) << text;
        return dir_ / name;
    }
    // The largest difference between the viewer's screenshot and prism-render's image of
    // `scene` at 64x48 and `spp` samples (the grid built, not read from a cache), or -1 where
    // prism-render failed or the sizes differ.
    double differenceFromPrismRender(const fs::path &shot, const fs::path &scene, int spp) {
        fs::path reference = dir_ / "render.exr";
        CliResult render =
            run(std::string(PRISM_RENDER_EXE) + " " + scene.string() + " --size 64x48 --spp " +
                std::to_string(spp) + " --quiet --no-cache -o " + reference.string());
        EXPECT_EQ(render.exitCode, 0) << render.out;
        prism::LoadedImage a = prism::readImage(shot), b = prism::readImage(reference);
        if (render.exitCode != 0 || a.pixels.size() != b.pixels.size())
            return -1.0;
        return largestDifference(a, b);
    }
    fs::path dir_;
};

// Showcase: triangles with a texture, glass, mirrors and two area lights, so the random numbers
// of soft shadows and the anti-aliasing strata are both compared. 320x240 with 4 samples keeps
// the run near 20 s on two cores.
TEST_F(PrismViewXvfb, ScriptedRunWithResizesMatchesPrismRender) {
    std::string scene = std::string(PRISM_SCENES_DIR) + "/showcase.scene";
    fs::path shot = dir_ / "view.exr", reference = dir_ / "render.exr";
    // Frames 0-2 trace at 320x240, frame 3 shrinks the window (the accumulation restarts at
    // 200x150), frame 6 restores it; the script ends once 4 samples have accumulated again.
    CliResult view = run(underXvfb(scene +
                                   " --size 320x240 --spp 4 --script-frames 10 "
                                   "--resize-at 3:200x150 --resize-at 6:320x240 "
                                   "--screenshot " +
                                   shot.string() + " --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    EXPECT_EQ(view.out.find("validation"), std::string::npos) << view.out;
    size_t small = view.out.find("swapchain 200x150");
    ASSERT_NE(small, std::string::npos) << "the window was not resized:\n" << view.out;
    EXPECT_NE(view.out.find("swapchain 320x240", small), std::string::npos) << view.out;
    ASSERT_TRUE(fs::exists(shot));
    ASSERT_TRUE(fs::exists(dir_ / "view.png"));

    CliResult render = run(std::string(PRISM_RENDER_EXE) + " " + scene + " --size 320x240 " +
                           "--spp 4 --quiet --validation -o " + reference.string());
    ASSERT_EQ(render.exitCode, 0) << render.out;

    prism::LoadedImage a = prism::readImage(shot), b = prism::readImage(reference);
    ASSERT_EQ(a.width, 320);
    ASSERT_EQ(a.height, 240);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    // Same shader, specialization, rays and summation order: the images should be bit-identical.
    // The tolerance (1e-6, far below one 8-bit step of 1/255) only forgives a driver that
    // reorders float additions; any sampling or camera mismatch moves pixels by >1e-2.
    EXPECT_LE(largestDifference(a, b), 1e-6);

    // The screenshot carries prism-render's metadata.
    int spp = 0;
    for (const auto &[name, value] : a.metadata.ints)
        if (name == "prism:samplesPerPixel")
            spp = value;
    EXPECT_EQ(spp, 4);
    bool hasDevice = false, hasRays = false;
    for (const auto &[name, value] : a.metadata.strings) {
        hasDevice = hasDevice || name == "prism:device";
        hasRays =
            hasRays || (name == "prism:raysPrimary" && value == std::to_string(320 * 240 * 4));
    }
    EXPECT_TRUE(hasDevice);
    EXPECT_TRUE(hasRays) << "the primary ray count covers exactly the 4 accumulated samples";
}

// --frame shows that frame of the animation: moved instances (moving-instances) and a camera on
// its turntable (showcase-turntable), each as prism-render --frames draws it.
TEST_F(PrismViewXvfb, AFrameOfAnAnimationIsPrismRendersFrame) {
    struct Case {
        const char *scene, *frame;
    };
    for (const Case &c : {Case{"moving-instances", "30"}, Case{"showcase-turntable", "60"}}) {
        SCOPED_TRACE(c.scene);
        std::string scene = std::string(PRISM_SCENES_DIR) + "/" + c.scene + ".scene";
        std::string common = " --size 96x72 --spp 2 --grid regular --validation";
        fs::path shot = dir_ / (std::string(c.scene) + "-view.exr");
        fs::path reference = dir_ / (std::string(c.scene) + "-render.exr");
        CliResult view = run(underXvfb(scene + common + " --frame " + c.frame +
                                       " --script-frames 4 --screenshot " + shot.string()));
        ASSERT_EQ(viewExit(view), 0) << view.out;
        CliResult render = run(std::string(PRISM_RENDER_EXE) + " " + scene + common +
                               " --quiet --frames " + c.frame + " -o " + reference.string());
        ASSERT_EQ(render.exitCode, 0) << render.out;
        CliResult first = run(std::string(PRISM_RENDER_EXE) + " " + scene + common +
                              " --quiet -o " + (dir_ / "first.exr").string());
        ASSERT_EQ(first.exitCode, 0) << first.out;
        prism::LoadedImage a = prism::readImage(shot), b = prism::readImage(reference);
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        EXPECT_LE(largestDifference(a, b), 1e-6);
        EXPECT_GT(largestDifference(a, prism::readImage(dir_ / "first.exr")), 1e-2)
            << "the frame differs from frame 1";
    }
}

// An edit that breaks the scene shows its FILE:LINE message and keeps the last good scene.
TEST_F(PrismViewXvfb, BrokenReloadKeepsTheLastGoodScene) {
    fs::path good = write("good.scene", "camera eye 0 0 5 look 0 0 0\nlight 2 2 5\n"
                                        "sphere 0 0 0 1\nplane 0 -1 0 0 1 0\n");
    fs::path broken = write("broken.scene", "light 2 2 5\nsphere 0 0 0 oops\n");
    fs::path shot = dir_ / "view.exr";
    CliResult view = run(underXvfb(good.string() + " --size 64x48 --spp 2 --script-frames 6 " +
                                   "--script-reload 3:" + broken.string() + " --screenshot " +
                                   shot.string() + " --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    EXPECT_NE(view.out.find("broken.scene:2:"), std::string::npos) << view.out;
    double difference = differenceFromPrismRender(shot, good, 2);
    EXPECT_GE(difference, 0.0);
    EXPECT_LE(difference, 1e-6) << "the good scene stayed on screen";
}

// A reload that changes only a material keeps the grid (no build: the geometry's key is the
// same) and shows the edited scene exactly as prism-render renders it; one that moves a sphere
// builds anew.
TEST_F(PrismViewXvfb, MaterialEditReloadKeepsTheGrid) {
    const std::string geometry = "camera eye 0 0 5 look 0 0 0\nlight 2 2 5\n"
                                 "sphere 0 0 0 1 ball\nsphere 1.5 0 -1 0.5 ball\n";
    write("red.scene", "material ball color 0.9 0.1 0.1\n" + geometry);
    fs::path blue =
        write("blue.scene", "material ball color 0.1 0.2 0.9 specular 0.5\n" + geometry);
    fs::path moved = write("moved.scene", "material ball color 0.9 0.1 0.1\n"
                                          "camera eye 0 0 5 look 0 0 0\nlight 2 2 5\n"
                                          "sphere 0 0.5 0 1 ball\nsphere 1.5 0 -1 0.5 ball\n");
    fs::path shot = dir_ / "view.exr";
    CliResult view =
        run(underXvfb((dir_ / "red.scene").string() +
                      " --size 64x48 --spp 2 --script-frames 6 --script-reload 3:" + blue.string() +
                      " --screenshot " + shot.string() + " --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    EXPECT_NE(view.out.find("reloaded blue.scene (same geometry: grid kept)"), std::string::npos)
        << view.out;
    double difference = differenceFromPrismRender(shot, blue, 2);
    EXPECT_GE(difference, 0.0);
    EXPECT_LE(difference, 1e-6) << "the edited material is shown, with the kept grid";

    CliResult move = run(
        underXvfb((dir_ / "red.scene").string() +
                  " --size 64x48 --spp 1 --script-frames 4 --script-reload 2:" + moved.string()));
    ASSERT_EQ(viewExit(move), 0) << move.out;
    EXPECT_NE(move.out.find("reloaded moved.scene"), std::string::npos) << move.out;
    EXPECT_EQ(move.out.find("grid kept"), std::string::npos) << "geometry moved: built anew";
}

// A reload that only moves an instance keeps the prototypes' mesh grids and builds the level the
// instances are in alone (issue 31), and shows the moved scene exactly as prism-render does.
TEST_F(PrismViewXvfb, InstanceMoveReloadKeepsTheMeshGrids) {
    std::string bunny =
        (fs::path(PRISM_SCENES_DIR) / ".." / "models" / "bunny" / "bunny_lowres.obj").string();
    auto scene = [&](const std::string &x) {
        return "camera eye 0 1.5 7 look 0 0.8 0\nlight 2 4 5\n"
               "material cream color 0.88 0.82 0.7 specular 0.4\n"
               "mesh " +
               bunny +
               " cream scale 13 translate 0.22 -0.433 0.04 smooth as bunny\n"
               "place bunny translate -1.2 0 0\nplace bunny translate " +
               x + " 0 0\n";
    };
    write("two.scene", scene("1.2"));
    fs::path moved = write("moved.scene", scene("0.6"));
    fs::path shot = dir_ / "view.exr";
    CliResult view = run(
        underXvfb((dir_ / "two.scene").string() +
                  " --size 64x48 --spp 2 --script-frames 6 --script-reload 3:" + moved.string() +
                  " --screenshot " + shot.string() + " --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    EXPECT_NE(view.out.find("reloaded moved.scene (same meshes: their grids kept)"),
              std::string::npos)
        << view.out;
    double difference = differenceFromPrismRender(shot, moved, 2);
    EXPECT_GE(difference, 0.0);
    EXPECT_LE(difference, 1e-6) << "the moved bunny, over the kept mesh grid";

    // A changed prototype (its scale) is a new mesh: its grid is built anew, not kept.
    std::string rescaledText = scene("0.6");
    rescaledText.replace(rescaledText.find("scale 13"), 8, "scale 10");
    fs::path rescaled = write("rescaled.scene", rescaledText);
    CliResult second = run(
        underXvfb((dir_ / "two.scene").string() +
                  " --size 64x48 --spp 2 --script-frames 6 --script-reload 3:" + rescaled.string() +
                  " --screenshot " + shot.string() + " --validation"));
    ASSERT_EQ(viewExit(second), 0) << second.out;
    EXPECT_NE(second.out.find("reloaded rescaled.scene"), std::string::npos) << second.out;
    EXPECT_EQ(second.out.find("grids kept"), std::string::npos) << "a new mesh: built anew";
    difference = differenceFromPrismRender(shot, rescaled, 2);
    EXPECT_GE(difference, 0.0);
    EXPECT_LE(difference, 1e-6) << "the smaller bunny, over its own mesh grid";
}

// Far from the origin the viewer shows what it shows at the origin: the scene is centred on the
// camera when loaded, and a jump of 1000 view distances and back re-centres twice (a grid
// rebuild each). The whole image is compared with the unit scene's prism-render: at most 0.1%
// of pixels may differ by more than 2/255 (measured: none).
TEST_F(PrismViewXvfb, FarFromTheOriginAndBackLooksTheSame) {
    auto sceneAt = [](double x, double y, double z) {
        auto at = [&](double a, double b, double c) {
            return std::to_string(x + a) + " " + std::to_string(y + b) + " " +
                   std::to_string(z + c) + " ";
        };
        return "camera eye " + at(0.5, 1.5, 5) + "look " + at(0, 0.5, 0) + "\nlight " +
               at(3, 4, 4) + "\nmaterial mirror reflect 0.6 specular 0.5\nsphere " +
               at(-0.8, 0.6, 0) + "0.6 mirror\nsphere " + at(0.9, 0.5, 0.4) + "0.5\nplane " +
               at(0, 0, 0) + "0 1 0\n";
    };
    fs::path unit = write("unit.scene", sceneAt(0, 0, 0));
    fs::path far = write("far.scene", sceneAt(1e6, -2e5, 3e6));
    fs::path shot = dir_ / "view.exr", reference = dir_ / "render.exr";
    CliResult view =
        run(underXvfb(far.string() + " --size 96x72 --spp 1 --script-frames 4 " +
                      "--script-fly-away 1 --screenshot " + shot.string() + " --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    EXPECT_NE(view.out.find("origin moved to the camera (2)"), std::string::npos) << view.out;
    CliResult render = run(std::string(PRISM_RENDER_EXE) + " " + unit.string() +
                           " --size 96x72 --spp 1 --quiet -o " + reference.string());
    ASSERT_EQ(render.exitCode, 0) << render.out;
    prism::LoadedImage a = prism::readImage(shot), b = prism::readImage(reference);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    size_t differing = 0;
    for (size_t p = 0; p + 3 < a.pixels.size(); p += 4) {
        bool differs = false;
        for (size_t c = 0; c < 3; ++c)
            differs = differs || std::abs(a.pixels[p + c] - b.pixels[p + c]) > 2.0f / 255.0f;
        differing += differs ? 1 : 0;
    }
    EXPECT_LE(differing, size_t(96 * 72 / 1000)) << differing << " pixels differ";
}

// The viewer keeps what it built on disk as prism-render does (--cache): a second start reads
// the big OBJ's parse and the grid back, and shows the same image as a cold prism-render.
TEST_F(PrismViewXvfb, ASecondStartReadsTheMeshAndTheGridFromTheCache) {
    write("field.obj", prism::test::wavyFieldObj());
    fs::path scene = write("field.scene", "camera eye 0 3 4 look 0 0 0 fov 50\n"
                                          "light 2 5 3 color 1 1 1\n"
                                          "sphere 0 0.6 0 0.5\nmesh field.obj\n");
    fs::path cache = dir_ / "cache";
    std::string common = scene.string() + " --size 64x48 --cache " + cache.string();
    auto benchmark = [&]() {
        CliResult view = run(underXvfb(common + " --benchmark 2"));
        EXPECT_EQ(viewExit(view), 0) << view.out;
        std::istringstream lines(view.out);
        for (std::string line; std::getline(lines, line);)
            if (line.rfind("{", 0) == 0) // the report: the one line of JSON
                return nlohmann::json::parse(line);
        ADD_FAILURE() << "no report:\n" << view.out;
        return nlohmann::json::object();
    };
    auto entries = [&] {
        std::vector<std::string> names;
        for (const fs::directory_entry &e : fs::directory_iterator(cache))
            if (e.path().extension() == ".bin")
                names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    };
    nlohmann::json cold = benchmark();
    EXPECT_EQ(cold["grid_cache"]["state"], "miss");
    EXPECT_EQ(cold["obj_cache"]["misses"], 1);
    std::vector<std::string> stored = entries();
    nlohmann::json warm = benchmark();
    EXPECT_EQ(warm["grid_cache"]["state"], "hit");
    EXPECT_EQ(warm["obj_cache"]["hits"], 1);
    EXPECT_EQ(warm["obj_cache"]["misses"], 0);
    EXPECT_EQ(warm["rays"], cold["rays"]);
    // A third start, to a screenshot: from the cache again (nothing new stored), and the image
    // prism-render makes without one.
    fs::path shot = dir_ / "view.exr";
    CliResult view = run(underXvfb(common + " --spp 2 --script-frames 4 --screenshot " +
                                   shot.string() + " --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    EXPECT_EQ(entries(), stored);
    double difference = differenceFromPrismRender(shot, scene, 2);
    EXPECT_GE(difference, 0.0);
    EXPECT_LE(difference, 1e-6);
}

TEST_F(PrismViewXvfb, BenchmarkPrintsOneJsonLine) {
    fs::path scene = write("s.scene", "light 2 2 5\nsphere 0 0 0 1\n");
    CliResult view = run(underXvfb(scene.string() + " --size 64x48 --benchmark 8 --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    for (const char *key : {"\"frame_ms_median\"", "\"frame_ms_p95\"", "\"frame_ms_p99\"",
                            "\"mrays_per_s\"", "\"frames\":8"})
        EXPECT_NE(view.out.find(key), std::string::npos) << key << "\n" << view.out;
}

// OpenImageIO's ~260 libraries are mapped at the first texture or screenshot, not at the start
// (0.2-0.4 s before the window when prism-view linked them): the dynamic loader's own log
// (LD_DEBUG=files) says whether they were.
TEST_F(PrismViewXvfb, OpenImageIOIsLoadedOnlyForATextureOrAScreenshot) {
    fs::path scene = write("s.scene", "light 2 2 5\nsphere 0 0 0 1\n");
    CliResult untextured =
        run("LD_DEBUG=files " + underXvfb(scene.string() + " --size 64x48 --benchmark 2"));
    ASSERT_EQ(viewExit(untextured), 0) << untextured.out;
    EXPECT_EQ(untextured.out.find("libOpenImageIO"), std::string::npos)
        << "OpenImageIO was loaded for a view that reads and writes no image";
    fs::path shot = dir_ / "shot.png";
    CliResult screenshot =
        run("LD_DEBUG=files " + underXvfb(scene.string() + " --size 64x48 --spp 1 " +
                                          "--script-frames 2 --screenshot " + shot.string()));
    ASSERT_EQ(viewExit(screenshot), 0) << screenshot.out;
    EXPECT_TRUE(fs::is_regular_file(shot));
    EXPECT_NE(screenshot.out.find("libprism_oiio.so"), std::string::npos) << "not loaded late";
}

TEST_F(PrismViewXvfb, ErrorsSayWhatIsWrong) {
    fs::path broken = write("broken.scene", "sphere 0 0 0\n");
    CliResult scene = run(underXvfb(broken.string()));
    EXPECT_EQ(viewExit(scene), 1) << scene.out;
    EXPECT_NE(scene.out.find("broken.scene:1:"), std::string::npos) << scene.out;

    // No display at all: say so, and how to run headless.
    CliResult noDisplay = run("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(PRISM_VIEW_EXE) +
                              " " + broken.string());
    EXPECT_EQ(noDisplay.exitCode, 1);
    EXPECT_NE(noDisplay.out.find("needs a display"), std::string::npos) << noDisplay.out;
    EXPECT_NE(noDisplay.out.find("xvfb-run"), std::string::npos) << noDisplay.out;
}

} // namespace

// A view past lavapipe's loop limit (33,000 spheres without the grid: ~66,000 iterations for a
// lit pixel): the first frame is cut, prism-view switches to resumable tracing, and the
// screenshot equals prism-render's image, which is traced resumably too.
TEST_F(PrismViewXvfb, ViewPastTheLoopLimitIsTracedResumably) {
    std::string text = "camera eye 0 0 5 look 0 0 0\nlight 0 0 10\n";
    for (int i = 0; i < 33000; ++i)
        text += "sphere " + std::to_string(1000 + i) + " 1000 1000 0.1\n";
    text += "sphere 0 0 0 1.5\nsphere 0.5 0 7 0.5\n";
    fs::path scene = write("many.scene", text);
    fs::path shot = dir_ / "view.exr", reference = dir_ / "render.exr";
    CliResult view =
        run(underXvfb(scene.string() + " --grid off --size 32x24 --spp 1 " +
                      "--script-frames 4 --screenshot " + shot.string() + " --validation"));
    ASSERT_EQ(viewExit(view), 0) << view.out;
    EXPECT_NE(view.out.find("tracing resumably"), std::string::npos) << view.out;
    CliResult render = run(std::string(PRISM_RENDER_EXE) + " " + scene.string() +
                           " --grid off --size 32x24 --spp 1 --quiet -o " + reference.string());
    ASSERT_EQ(render.exitCode, 0) << render.out;
    prism::LoadedImage a = prism::readImage(shot), b = prism::readImage(reference);
    EXPECT_EQ(a.pixels, b.pixels);
}
