// prism-bench: times scenes under tracer variants (grid choices, features off) on one Vulkan
// device and prints a Markdown table: median GPU ms over several interleaved frames, Mrays/s,
// and each variant's time relative to the first variant of its scene.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_profile.h"
#include "bench_study.h"
#include "command_line.h"
#include "core/error.h"
#include "core/median.h"
#include "embree_baseline.h"
#include "render/ray_tracer.h"
#include "tool_environment.h"

using namespace prism;

namespace {

std::vector<std::string> splitList(const std::string &text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ','))
        if (!part.empty())
            parts.push_back(part);
    return parts;
}

void printTable(const std::vector<BenchResult> &results, const BenchSettings &s,
                const std::string &device) {
    std::printf("Device: %s; %ux%u, %u spp, depth %u; median of %u frames after a warm-up.%s\n\n",
                device.c_str(), s.width, s.height, s.samplesPerPixel, s.maxDepth, s.runs,
                s.embreeBaseline ? " embree: Intel Embree on the CPU, all cores, primary and "
                                   "shadow rays in 8-wide packets, wall time (both of its times)."
                                 : "");
    std::printf("Trace ms: GPU timestamps around the dispatches; wall ms: the host's clock from "
                "recording a frame to its fence. Mrays/s at the median trace ms.\n\n");
    std::printf("| scene | variant | primitives | grid | max/cell | bytes/prim | cells/ray | "
                "tests/ray | build ms | trace ms (median) | wall ms (median) | Mrays/s | rays | "
                "vs first |%s\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|%s\n",
                s.embreeBaseline ? " Mrays/s vs Embree | by wall time |" : "",
                s.embreeBaseline ? "---|---|" : "");
    double first = 0.0;
    std::string scene;
    for (const BenchResult &r : results) {
        if (r.scene != scene) {
            scene = r.scene;
            first = r.medianMs();
        }
        std::string vsEmbree;
        for (const BenchResult &e : results)
            if (s.embreeBaseline && e.scene == r.scene && e.variant == "embree") {
                char text[32];
                std::snprintf(text, sizeof text, " %.2f | %.2f |",
                              r.mraysPerSecond() / e.mraysPerSecond(),
                              r.wallMraysPerSecond() / e.wallMraysPerSecond());
                vsEmbree = text;
            }
        std::printf("| %s | %s | %llu | %s | %u | %.0f | %.2f | %.2f | %.1f | %.1f | %.1f | %.2f | "
                    "%llu | %.2f |%s\n",
                    r.scene.c_str(), r.variant.c_str(), (unsigned long long)r.primitives,
                    r.grid.c_str(), r.maxPerCell,
                    double(r.gridBytes) / double(std::max<uint64_t>(1, r.primitives)),
                    r.walk.cellsPerRay, r.walk.testsPerRay, r.buildMs, r.medianMs(),
                    r.medianWallMs(), r.mraysPerSecond(), (unsigned long long)r.rays.total(),
                    first > 0.0 ? r.medianMs() / first : 0.0, vsEmbree.c_str());
    }
}

// With interleaved scenes: each scene's per-ray cost against the first scene's, variant by
// variant (Embree's too), as the median of each run's ratio: the run's frames were taken back
// to back, so the machine's drift between runs cancels. Every scene has `perScene` results in
// the same order (runStudy), so a result's base is the first scene's result at its place.
struct SceneRatio {
    std::string scene, variant;
    double byTrace = 0.0, byWall = 0.0;
};

std::vector<SceneRatio> sceneRatios(const std::vector<BenchResult> &results, size_t perScene) {
    std::vector<SceneRatio> ratios;
    for (size_t i = perScene; perScene > 0 && i < results.size(); ++i) {
        const BenchResult &r = results[i], &base = results[i % perScene];
        if (r.rays.total() == 0 || base.rays.total() == 0)
            continue;
        auto ratio = [&](const std::vector<double> &ms, const std::vector<double> &baseMs) {
            std::vector<double> perRun;
            for (size_t k = 0; k < std::min(ms.size(), baseMs.size()); ++k)
                perRun.push_back((ms[k] / double(r.rays.total())) /
                                 (baseMs[k] / double(base.rays.total())));
            return median(perRun);
        };
        ratios.push_back(
            {r.scene, r.variant, ratio(r.frameMs, base.frameMs), ratio(r.wallMs, base.wallMs)});
    }
    return ratios;
}

void printSceneRatios(const std::vector<SceneRatio> &ratios, const std::string &firstScene) {
    if (ratios.empty())
        return; // one scene: nothing to set against it
    std::printf("\nPer-ray cost against %s, the same variant (median over the runs of each run's "
                "ratio):\n\n| scene | variant | by trace ms | by wall ms |\n|---|---|---|---|\n",
                firstScene.c_str());
    for (const SceneRatio &r : ratios)
        std::printf("| %s | %s | %.2f | %.2f |\n", r.scene.c_str(), r.variant.c_str(), r.byTrace,
                    r.byWall);
}

nlohmann::json toJson(const PhaseProfile &p) {
    const auto &ns = p.nsPerSample;
    return {{"ns_per_sample",
             {{"camera", ns[gpu::kPhaseCamera]},
              {"primary_walk", ns[gpu::kPhasePrimaryWalk]},
              {"secondary_walks", ns[gpu::kPhaseSecondaryWalk]},
              {"shadow_walks", ns[gpu::kPhaseShadowWalk]},
              {"shading", ns[gpu::kPhaseShading]},
              {"stack", ns[gpu::kPhaseStack]},
              {"output", ns[gpu::kPhaseOutput]},
              {"primitive_tests", ns[gpu::kPhasePrimitiveTests]},
              {"clock_reads", ns[gpu::kPhaseClockReads]},
              {"other", p.nsOutsidePhases()},
              {"total", ns[gpu::kPhaseTotal]}}},
            {"frame_ms", p.frameMs},
            {"frame_ns_per_sample", p.nsPerFrameSample}};
}

nlohmann::json toJson(const BenchResult &r) {
    nlohmann::json profile;
    if (r.profile)
        profile = {{"phases", toJson(r.profile->phases)},
                   {"walk_detail", toJson(r.profile->detail)}};
    return {
        {"scene", r.scene},
        {"variant", r.variant},
        {"primitives", r.primitives},
        {"grid", r.grid},
        {"max_per_cell", r.maxPerCell},
        {"grid_bytes", r.gridBytes},
        {"scene_bytes", r.sceneBytes},
        {"cells_per_primary_ray", r.walk.cellsPerRay},
        {"tests_per_primary_ray", r.walk.testsPerRay},
        {"build_ms", r.buildMs},
        {"frame_ms", r.frameMs},
        {"trace_ms_median", r.medianMs()},
        {"wall_ms", r.wallMs},
        {"wall_ms_median", r.medianWallMs()},
        {"mrays_per_s", r.mraysPerSecond()},
        {"rays",
         {{"primary", r.rays.primary}, {"shadow", r.rays.shadow}, {"secondary", r.rays.secondary}}},
        {"profile", profile}};
}

} // namespace

int main(int argc, char **argv) {
    CLI::App app{"prism-bench: times scenes under tracer variants, interleaving frames so that "
                 "ratios between variants hold on a noisy machine."};
    app.set_version_flag("--version", "prism-bench 0.1.0");
    std::vector<std::string> scenes;
    std::string size = "1024x768", variantList = "auto", jsonPath, deviceFilter;
    BenchSettings settings;
    app.add_option("SCENES", scenes, "Scene files")->required()->check(CLI::ExistingFile);
    app.add_option("--size", size, "Image size WxH")->default_val(size);
    app.add_option("--spp", settings.samplesPerPixel, "Samples per pixel")
        ->check(CLI::Range(1u, kMaxSamplesPerPixel))
        ->default_val(1);
    app.add_option("--seed", settings.seed,
                   "Sampling seed (as prism-render's): another independent set of pixel and "
                   "area-light samples; 0, the default, the usual one")
        ->check(CLI::Range(0u, gpu::kMaxSeed))
        ->default_val(0u);
    app.add_option("--depth", settings.maxDepth, "Maximum ray depth")
        ->check(CLI::Range(1u, 16u))
        ->default_val(5);
    app.add_option("--runs", settings.runs, "Timed frames per variant")
        ->check(CLI::Range(1u, 1000u))
        ->default_val(5);
    app.add_option(
           "--variants", variantList,
           "Comma-separated variants: auto, regular, off, adaptive, two-level, grid=N|NxNyNz, "
           "density=L, lean (the grid built as prism-render builds it for one image of a big "
           "mesh: adaptive cells not expanded, cells listing primitive ids), "
           "no-reflection, no-refraction, no-shadows, no-cull (the full tracer on every tile, "
           "also those whose camera rays miss everything), no-plane-tiles (the grid in tiles "
           "that see only planes too), no-tile-starts (camera rays walk the grid from its entry, "
           "not from their tile's start distance), start-boxes=N (at most N start blocks, "
           "projected on the host each frame; 16384 by default), bit-reversed-rows (the tile "
           "list's rows in bit-reversed order, not every n-th row to each of lavapipe's n "
           "threads), no-cell-primitives (cells list "
           "primitive ids, not the triangles or spheres themselves), no-fold (the tracer's "
           "specialization left to the driver, not folded into its module first), texel or "
           "storage (how the hot "
           "arrays "
           "are read), resumable (the loop-budget tracer from the first frame); join parts with +. "
           "For the studies (docs/studies) only, methods Prism replaced: offset=E (the "
           "original's fixed ray offset of E scene units; offset=relative is Prism's) and "
           "triangle=mt (Moller-Trumbore; triangle=watertight is Prism's). flat: the scene's "
           "instances "
           "written out as plain triangles (what instancing saves)")
        ->default_val(variantList);
    app.add_flag("--keep-origin", settings.keepOrigin,
                 "For the studies: trace each scene in its file's coordinates instead of moving "
                 "the origin to the camera as every renderer does (shows what that protects)");
    app.add_option("--save-images", settings.imageDir,
                   "For the studies: write each variant's first frame to DIR/SCENE_VARIANT.exr "
                   "(linear RGBA), to compare variants' images")
        ->check(CLI::ExistingDirectory);
    std::string baseline;
    app.add_option("--baseline", baseline,
                   "embree: also trace the same camera rays and one shadow ray per light per hit "
                   "with Intel Embree on all cores (CPU), interleaved with the variants; Prism's "
                   "Mrays/s is then given as a ratio to it (use --depth 1 for the same rays)")
        ->check(CLI::IsMember({"embree"}));
    app.add_flag("--profile", settings.profile,
                 "Also run each variant with in-shader clocks (VK_KHR_shader_clock) and print "
                 "where its time goes: camera, walks, shading, per pixel sample");
    app.add_flag("--interleave-scenes", settings.interleaveScenes,
                 "Set up every scene first (all in memory at once) and take each run's frames "
                 "across all scenes in turn, then print each scene's per-ray cost against the "
                 "first scene's: for ratios between scenes (cost against scene size) that hold "
                 "on a noisy machine");
    app.add_option("--json", jsonPath, "Also write every result (all frame times) as JSON");
    app.add_option("--device", deviceFilter, "First Vulkan device whose name contains this");
    bool validation = false;
    bool quiet = false;
    app.add_flag("--quiet", quiet,
                 "No progress on stderr (a rewritten line on a terminal, a line a step in a log)");
    app.add_flag("--validation", validation,
                 "Enable Vulkan validation layers (also PRISM_VALIDATION=1); any message fails "
                 "the run. Timings under validation are not comparable with others");
    std::vector<BenchVariant> variants;
    if (auto status = parseCommandLine("prism-bench", app, argc, argv, [&] {
            unsigned w = 0, h = 0;
            char x = 0;
            std::istringstream in(size);
            if (!(in >> w >> x >> h) || x != 'x' || w == 0 || h == 0 || !in.eof())
                throw Error("--size " + size + ": expected WxH, e.g. 1024x768");
            settings.width = w;
            settings.height = h;
            settings.embreeBaseline = baseline == "embree";
            for (const std::string &v : splitList(variantList))
                variants.push_back(parseBenchVariant(v));
            if (variants.empty())
                throw Error("--variants: no variant given");
        }))
        return *status;
    try {
        if (settings.embreeBaseline && !embreeAvailable())
            throw Error("--baseline embree: prism-bench was built without Embree (install "
                        "libembree-dev with tools/scripts/install-deps.sh and reconfigure)");
        vk::ContextOptions contextOptions;
        contextOptions.deviceNameFilter = deviceFilter;
        contextOptions.shaderClock = settings.profile;
        contextOptions.validation = validationWanted(validation);
        vk::Context context(contextOptions);
        // Progress rewrites one line of a terminal; a log or a pipe gets a line a step instead
        // of carriage returns (which step ran when is what a log of a benchmark is read for).
        bool terminal = ::isatty(2) == 1;
        std::vector<BenchResult> results =
            runStudy(context, scenes, variants, settings, [&](const std::string &what) {
                if (quiet)
                    return;
                std::fprintf(stderr, terminal ? "\rprism-bench: %-60s" : "prism-bench: %s\n",
                             what.c_str());
                std::fflush(stderr);
            });
        if (terminal && !quiet)
            std::fprintf(stderr, "\n");
        // Every variant, the profiling shader included, ran under the layers when asked: a
        // message fails the run rather than printing timings of a frame the device misread.
        if (context.validationMessageCount() > 0)
            throw Error(std::to_string(context.validationMessageCount()) +
                        " Vulkan validation messages (printed above)");
        printTable(results, settings, context.deviceName());
        std::vector<SceneRatio> ratios;
        if (settings.interleaveScenes && !results.empty()) {
            ratios = sceneRatios(results, variants.size() + (settings.embreeBaseline ? 1 : 0));
            printSceneRatios(ratios, results.front().scene);
        }
        if (settings.profile)
            printProfileTable(results);
        if (!jsonPath.empty()) {
            nlohmann::json all = nlohmann::json::array();
            for (const BenchResult &r : results)
                all.push_back(toJson(r));
            nlohmann::json sceneRatioRows = nlohmann::json::array();
            for (const SceneRatio &r : ratios)
                sceneRatioRows.push_back({{"scene", r.scene},
                                          {"variant", r.variant},
                                          {"per_ray_cost_by_trace", r.byTrace},
                                          {"per_ray_cost_by_wall", r.byWall}});
            std::string tmp = jsonPath + ".tmp";
            std::ofstream(tmp) << nlohmann::json{{"device", context.deviceName()},
                                                 {"width", settings.width},
                                                 {"height", settings.height},
                                                 {"spp", settings.samplesPerPixel},
                                                 {"seed", settings.seed},
                                                 {"depth", settings.maxDepth},
                                                 {"runs", settings.runs},
                                                 {"interleave_scenes", settings.interleaveScenes},
                                                 {"scene_ratios", sceneRatioRows},
                                                 {"results", all}}
                                      .dump(1)
                               << "\n";
            std::rename(tmp.c_str(), jsonPath.c_str());
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "prism-bench: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
