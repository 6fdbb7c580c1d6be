// prism-bench as a user meets it: help, a bad variant, a tiny study's table and JSON, and the
// studies' switches (variants of replaced methods, saved images, the file's origin).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "io/image_reader.h"
#include "missing_tool.h"
#include "temp_dir_fixture.h"

namespace fs = std::filesystem;
using prism::test::CliResult;

namespace {

CliResult bench(const std::string &args) {
    return prism::test::runTool(PRISM_BENCH_EXE, args);
}

// Each test gets a directory of its own holding one tiny scene.
class PrismBenchCli : public prism::test::TempDirTest {
protected:
    fs::path scene_ = write("tiny.scene", "light 2 2 5\nsphere 0 0 0 1\nsphere 1 1 -1 0.5\n"
                                          "plane 0 -1 0 0 1 0\n");
};

TEST_F(PrismBenchCli, HelpNamesTheVariants) {
    CliResult r = bench("--help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char *word : {"--variants", "--runs", "density=L", "no-shadows", "offset=E",
                             "triangle=mt", "start-boxes=N", "--keep-origin", "--save-images",
                             "For the studies", "--interleave-scenes"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

// --version answers without a scene, as the other tools do (issue 35).
TEST_F(PrismBenchCli, VersionNeedsNoScene) {
    CliResult r = bench("--version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("prism-bench 0.1.0"), std::string::npos) << r.out;
}

TEST_F(PrismBenchCli, BadVariantIsNamed) {
    for (const char *variant :
         {"fast", "offset=0", "offset=-1", "offset=x", "offset=inf", "density=0", "triangle=fast",
          "start-boxes=0", "start-boxes=0.5", "start-boxes=1e30"}) {
        CliResult r = bench(scene_.string() + " --variants auto," + variant);
        EXPECT_NE(r.exitCode, 0) << variant;
        EXPECT_NE(r.out.find(variant), std::string::npos) << r.out;
    }
}

// The studies' variants (docs/studies) render, and the default variant's saved image is the very
// image prism-render makes of the scene: the variants' switches cost ordinary renders nothing.
TEST_F(PrismBenchCli, SavedImagesOfTheStudiesVariants) {
    fs::path scene = write("mesh.scene", "light 2 2 5\nsphere 0 0 0 1\nmaterial m reflect 0.5\n"
                                         "triangle -2 -1 -1 2 -1 -1 0 2 -1.5 m\n"
                                         "plane 0 -1 0 0 1 0 m\n");
    fs::path images = dir() / "images";
    fs::create_directory(images);
    CliResult r = bench(scene.string() +
                        " --size 24x16 --runs 1 --variants "
                        "auto,offset=0.01,offset=1e-4,triangle=mt "
                        "--save-images " +
                        images.string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    fs::path rendered = dir() / "render.exr";
    ASSERT_EQ(prism::test::runTool(PRISM_RENDER_EXE, scene.string() + " -o " + rendered.string() +
                                                         " --size 24x16 --quiet")
                  .exitCode,
              0);
    prism::LoadedImage plain = prism::readImage(rendered);
    for (const char *variant : {"auto", "offset=0.01", "offset=1e-4", "triangle=mt"}) {
        fs::path file = images / ("mesh_" + std::string(variant) + ".exr");
        ASSERT_TRUE(fs::is_regular_file(file)) << file;
        prism::LoadedImage image = prism::readImage(file);
        ASSERT_EQ(image.pixels.size(), plain.pixels.size()) << variant;
        size_t differing = 0;
        for (size_t i = 0; i < image.pixels.size(); ++i)
            differing += image.pixels[i] != plain.pixels[i];
        if (std::string(variant) == "auto")
            EXPECT_EQ(differing, 0u) << "the default variant's image is prism-render's";
        else // the same scene by another method: close, if not identical
            EXPECT_LT(differing, image.pixels.size() / 10) << variant;
    }
}

// --seed draws the samples prism-render draws under the same seed (a benchmark of another set
// of samples is a benchmark of the images a user gets with it), and another set than seed 0's.
TEST_F(PrismBenchCli, SeedDrawsPrismRendersSamples) {
    fs::path images = dir() / "seeded";
    fs::create_directory(images);
    std::string common = scene_.string() + " --size 24x16 --spp 2 ";
    CliResult r = bench(common + "--runs 1 --seed 7 --save-images " + images.string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const char *seed : {"7", "0"}) {
        fs::path rendered = dir() / ("seed" + std::string(seed) + ".exr");
        ASSERT_EQ(prism::test::runTool(PRISM_RENDER_EXE, common + "--seed " + seed + " -o " +
                                                             rendered.string() + " --quiet")
                      .exitCode,
                  0);
        prism::LoadedImage benched = prism::readImage(images / "tiny_auto.exr");
        prism::LoadedImage plain = prism::readImage(rendered);
        ASSERT_EQ(benched.pixels.size(), plain.pixels.size());
        size_t differing = 0;
        for (size_t i = 0; i < plain.pixels.size(); ++i)
            differing += benched.pixels[i] != plain.pixels[i];
        if (std::string(seed) == "7")
            EXPECT_EQ(differing, 0u) << "prism-bench --seed 7 is not prism-render's seed 7";
        else
            EXPECT_GT(differing, 0u) << "seed 7 drew seed 0's samples";
    }
}

TEST_F(PrismBenchCli, KeepOriginTracesTheFileCoordinates) {
    // 1e6 from the origin, uncentred floats are 1/16 apart: the picture changes (what the
    // centring protects against), where the centred run gives the picture of the scene.
    fs::path far = write("far.scene", "camera eye 1e6 1000001 1000005 look 1e6 1e6 1e6\n"
                                      "light 1000002 1000002 1000005\nsphere 1e6 1e6 1e6 1\n"
                                      "sphere 1000000.7 1000000.5 1000000.9 0.3\n");
    std::vector<float> pixels[2];
    for (int keep = 0; keep < 2; ++keep) {
        fs::path images = dir() / (keep ? "kept" : "centred");
        fs::create_directory(images);
        CliResult r = bench(far.string() + " --size 32x24 --runs 1 --save-images " +
                            images.string() + (keep ? " --keep-origin" : ""));
        ASSERT_EQ(r.exitCode, 0) << r.out;
        pixels[keep] = prism::readImage(images / "far_auto.exr").pixels;
    }
    ASSERT_EQ(pixels[0].size(), pixels[1].size());
    size_t differing = 0;
    for (size_t i = 0; i < pixels[0].size(); ++i)
        differing += std::abs(pixels[0][i] - pixels[1][i]) > 0.02f;
    EXPECT_GT(differing, 0u) << "--keep-origin changed nothing 1e6 from the origin";
}

TEST_F(PrismBenchCli, TableAndJsonForEveryVariant) {
    fs::path json = dir() / "out.json";
    CliResult r = bench(scene_.string() +
                        " --size 16x12 --runs 3 --variants "
                        "auto,off,grid=3+no-shadows --json " +
                        json.string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.stdoutOnly.find("| tiny | grid=3+no-shadows |"), std::string::npos) << r.stdoutOnly;
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(json));
    ASSERT_EQ(doc["results"].size(), 3u);
    for (const auto &result : doc["results"]) {
        EXPECT_EQ(result["frame_ms"].size(), 3u);
        ASSERT_EQ(result["wall_ms"].size(), 3u);
        // The wall clock runs from recording to the fence, round the timestamps.
        for (size_t k = 0; k < 3; ++k)
            EXPECT_GE(result["wall_ms"][k].get<double>(), result["frame_ms"][k].get<double>());
        EXPECT_EQ(result["rays"]["primary"].get<uint64_t>(), 16u * 12u);
    }
    EXPECT_GT(doc["results"][0]["rays"]["shadow"].get<uint64_t>(), 0u);
    EXPECT_EQ(doc["results"][2]["rays"]["shadow"].get<uint64_t>(), 0u); // shadows switched off
    EXPECT_EQ(doc["results"][1]["grid"], "off");
    EXPECT_EQ(doc["results"][2]["grid"], "3x3x3");
}

// --interleave-scenes takes each run's frames across the scenes in turn (scene after scene
// without it), and prints each scene's per-ray cost against the first's: the median over the
// runs of each run's ratio, as the JSON's frame times give it.
TEST_F(PrismBenchCli, InterleavedScenesGiveEachScenesCostAgainstTheFirst) {
    fs::path more = write("more.scene", "light 2 2 5\nsphere 0 0 0 1\nsphere 1 1 -1 0.5\n"
                                        "sphere -1 0.5 0 0.4\nsphere 0.5 -0.5 1 0.3\n");
    fs::path json = dir() / "out.json";
    std::string scenes = scene_.string() + " " + more.string() + " --size 16x12 --runs 3 ";
    CliResult plain = bench(scenes + "--variants auto,off");
    ASSERT_EQ(plain.exitCode, 0) << plain.out;
    EXPECT_LT(plain.out.find("tiny off: frame 3/3"), plain.out.find("more auto: frame 1/3"));
    EXPECT_EQ(plain.stdoutOnly.find("Per-ray cost against"), std::string::npos);
    // Not a terminal here: a line a step, without the carriage returns of a terminal's line.
    EXPECT_EQ(plain.out.find('\r'), std::string::npos) << plain.out;
    CliResult quiet = bench(scenes + "--variants auto --quiet");
    ASSERT_EQ(quiet.exitCode, 0) << quiet.out;
    EXPECT_EQ(quiet.out.find("prism-bench: "), std::string::npos) << quiet.out;
    CliResult r = bench(scenes + "--variants auto,off --interleave-scenes --json " + json.string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    size_t secondScene = r.out.find("more auto: frame 1/3"),
           firstAgain = r.out.find("tiny auto: frame 2/3");
    ASSERT_NE(secondScene, std::string::npos) << r.out;
    ASSERT_NE(firstAgain, std::string::npos) << r.out;
    EXPECT_LT(secondScene, firstAgain) << "frames not interleaved";
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(json));
    EXPECT_EQ(doc["interleave_scenes"], true);
    EXPECT_EQ(doc["runs"], 3);
    ASSERT_EQ(doc["scene_ratios"].size(), 2u);
    ASSERT_EQ(doc["results"].size(), 4u);
    EXPECT_EQ(doc["results"][0]["scene"], "tiny");
    EXPECT_EQ(doc["results"][2]["scene"], "more");
    for (int v = 0; v < 2; ++v) {
        const auto &base = doc["results"][v], &other = doc["results"][v + 2];
        std::vector<double> ratios;
        for (size_t k = 0; k < 3; ++k)
            ratios.push_back((other["frame_ms"][k].get<double>() /
                              double(other["rays"]["primary"].get<uint64_t>() +
                                     other["rays"]["shadow"].get<uint64_t>() +
                                     other["rays"]["secondary"].get<uint64_t>())) /
                             (base["frame_ms"][k].get<double>() /
                              double(base["rays"]["primary"].get<uint64_t>() +
                                     base["rays"]["shadow"].get<uint64_t>() +
                                     base["rays"]["secondary"].get<uint64_t>())));
        std::sort(ratios.begin(), ratios.end());
        std::string row = "| more | " + other["variant"].get<std::string>() + " | ";
        size_t at = r.stdoutOnly.find(row, r.stdoutOnly.find("Per-ray cost against tiny"));
        ASSERT_NE(at, std::string::npos) << row << "\n" << r.stdoutOnly;
        double printed = std::stod(r.stdoutOnly.substr(at + row.size()));
        EXPECT_NEAR(printed, ratios[1], 0.005 + 1e-9) << row;
        const auto &saved = doc["scene_ratios"][v];
        EXPECT_EQ(saved["scene"], "more");
        EXPECT_EQ(saved["variant"], other["variant"]);
        EXPECT_NEAR(saved["per_ray_cost_by_trace"].get<double>(), ratios[1], 1e-9);
    }
}

// Embree traces the very rays Prism traces at depth 1: every camera ray, and one shadow ray
// per light from each hit on a surface facing it. Their counts must agree.
TEST_F(PrismBenchCli, EmbreeBaselineTracesTheSameRays) {
    fs::path json = dir() / "out.json";
    CliResult r = bench(scene_.string() + " --size 16x12 --depth 1 --runs 2 --variants auto,off " +
                        "--baseline embree --json " + json.string());
    if (r.exitCode != 0 && r.out.find("built without Embree") != std::string::npos)
        PRISM_MISSING_TEST_TOOL("prism-bench was built without Embree (Debian: libembree-dev)");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.stdoutOnly.find("Mrays/s vs Embree"), std::string::npos) << r.stdoutOnly;
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(json));
    ASSERT_EQ(doc["results"].size(), 3u);
    const auto &embree = doc["results"][2];
    EXPECT_EQ(embree["variant"], "embree");
    EXPECT_EQ(embree["frame_ms"].size(), 2u);
    for (int v = 0; v < 2; ++v) {
        EXPECT_EQ(doc["results"][v]["rays"]["primary"], embree["rays"]["primary"]);
        EXPECT_EQ(doc["results"][v]["rays"]["shadow"], embree["rays"]["shadow"]);
    }
    EXPECT_GT(embree["rays"]["shadow"].get<uint64_t>(), 0u);
}

TEST_F(PrismBenchCli, UnknownBaselineIsRefused) {
    CliResult r = bench(scene_.string() + " --baseline ospray");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("ospray"), std::string::npos) << r.out;
}

} // namespace

// --profile: every phase the scene has takes time, the phases it lacks take none, and the
// in-shader clocks cannot account for more than the frame's time on every core (their total
// over the frame's time is the number of cores busy; how many were is up to a shared machine).
// Under validation, so that the profiling shader's variants are checked by the layers too (a
// message fails the run).
TEST_F(PrismBenchCli, ProfileTimesThePhasesTheSceneHas) {
    fs::path mirror = write("mirror.scene", "light 2 2 5\nmaterial m reflect 0.5\n"
                                            "sphere 0 0 0 1 m\nplane 0 -1 0 0 1 0\n");
    fs::path json = dir() / "out.json";
    CliResult r = bench(scene_.string() + " " + mirror.string() +
                        " --size 32x24 --depth 2 --runs 2 --profile --validation --json " +
                        json.string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.stdoutOnly.find("Where the time goes"), std::string::npos) << r.stdoutOnly;
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(json));
    ASSERT_EQ(doc["results"].size(), 2u);
    for (int s = 0; s < 2; ++s) {
        const auto &phases = doc["results"][s]["profile"]["phases"];
        const auto &ns = phases["ns_per_sample"];
        SCOPED_TRACE(doc["results"][s]["scene"].get<std::string>());
        // Every phase a frame always passes through (a phase dropped from the shader's clocks
        // reads 0), and the measured phases within the total (one counted twice overflows it;
        // "other" is the total less them and less the clock reads, which are an estimate).
        for (const char *phase :
             {"camera", "primary_walk", "shadow_walks", "shading", "stack", "output", "clock_reads"})
            EXPECT_GT(ns[phase].get<double>(), 0.0) << phase;
        EXPECT_GE(ns["other"].get<double>() + ns["clock_reads"].get<double>(), 0.0);
        EXPECT_EQ(ns["primitive_tests"].get<double>(), 0.0); // level 1 has no clocks in walks
        double cores = ns["total"].get<double>() / phases["frame_ns_per_sample"].get<double>();
        EXPECT_GT(cores, 0.0);
        EXPECT_LE(cores, double(std::thread::hardware_concurrency()) * 1.1);
        const auto &detail = doc["results"][s]["profile"]["walk_detail"]["ns_per_sample"];
        EXPECT_GT(detail["primitive_tests"].get<double>(), 0.0);
        EXPECT_LT(detail["primitive_tests"].get<double>(),
                  detail["primary_walk"].get<double>() + detail["shadow_walks"].get<double>() +
                      detail["secondary_walks"].get<double>());
    }
    // Only the mirror sends rays on: tiny.scene has no reflective material.
    EXPECT_EQ(doc["results"][0]["profile"]["phases"]["ns_per_sample"]["secondary_walks"], 0.0);
    EXPECT_GT(doc["results"][1]["profile"]["phases"]["ns_per_sample"]["secondary_walks"], 0.0);
}

// The resumable variant (the loop-budget tracer from the first frame) traces the same rays.
TEST_F(PrismBenchCli, ResumableVariantTracesTheSameRays) {
    fs::path json = dir() / "out.json";
    CliResult r = bench(scene_.string() + " --size 16x12 --runs 1 --variants auto,auto+resumable " +
                        "--json " + json.string());
    ASSERT_EQ(r.exitCode, 0) << r.out;
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(json));
    ASSERT_EQ(doc["results"].size(), 2u);
    EXPECT_EQ(doc["results"][0]["rays"], doc["results"][1]["rays"]);
    EXPECT_GT(doc["results"][1]["rays"]["shadow"].get<uint64_t>(), 0u);
}
