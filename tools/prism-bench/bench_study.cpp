#include "bench_study.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

#include "bench_profile.h"
#include "core/error.h"
#include "core/median.h"
#include "core/timer.h"
#include "embree_baseline.h"
#include "io/image_writer.h"
#include "render/ray_tracer.h"
#include "scene/instance_flattening.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"

namespace prism {
namespace {

// The frame just traced, as an EXR (linear RGBA), unless the device reported validation
// messages: then the image may be wrong and the run stops, as prism-render does.
void saveImage(vk::Context &context, RayTracer &tracer, const BenchSettings &settings,
               const std::filesystem::path &path) {
    if (context.validationMessageCount() > 0)
        throw Error(std::to_string(context.validationMessageCount()) +
                    " Vulkan validation messages (printed above); refusing to write " +
                    path.string());
    TracedImage traced = tracer.readback(settings.samplesPerPixel);
    OutputImage image;
    image.width = int(traced.width);
    image.height = int(traced.height);
    image.rgba = std::move(traced.rgba);
    writeImage(path, image, ImageMetadata{});
}

} // namespace

double BenchResult::medianMs() const {
    return median(frameMs);
}

double BenchResult::medianWallMs() const {
    return median(wallMs);
}

namespace {
double mraysPerSecond(const RayCounts &rays, double ms) {
    return ms > 0.0 ? double(rays.total()) / (ms * 1000.0) : 0.0;
}
} // namespace

double BenchResult::mraysPerSecond() const {
    return prism::mraysPerSecond(rays, medianMs());
}

double BenchResult::wallMraysPerSecond() const {
    return prism::mraysPerSecond(rays, medianWallMs());
}

namespace {

// One scene's variants, set up (grids built, tracers made, a warm-up frame each) before any
// timed frame. Held by pointer: the variants' scene pointers point into it.
struct SceneStudy {
    std::string name;
    Scene source;              // centred on the camera unless BenchSettings::keepOrigin
    std::optional<Scene> flat; // the scene with its instances written out, once
    std::vector<const Scene *> variantScenes;
    std::vector<std::unique_ptr<RayTracer>> tracers;
    std::vector<Grid> grids; // kept for the profiling runs only
    std::unique_ptr<EmbreeBaseline> embree;
    std::vector<BenchResult> results; // the variants', then Embree's
};

std::unique_ptr<SceneStudy> setUpScene(vk::Context &context, const std::string &path,
                                       const std::vector<BenchVariant> &variants,
                                       const BenchSettings &settings,
                                       const std::function<void(const std::string &)> &progress) {
    auto study = std::make_unique<SceneStudy>();
    SceneStudy &s = *study;
    s.source = loadScene(path);
    if (!settings.keepOrigin)
        centerOnCamera(s.source);
    s.name = std::filesystem::path(path).stem().string();
    for (const BenchVariant &variant : variants) {
        progress(s.name + " " + variant.name + ": build + warm-up");
        if (variant.flattenInstances && !s.flat)
            s.flat = flattenInstances(s.source);
        const Scene &scene = variant.flattenInstances ? *s.flat : s.source;
        s.variantScenes.push_back(&scene);
        BenchResult r;
        r.scene = s.name;
        r.variant = variant.name;
        r.primitives = scene.finitePrimitiveCount() + scene.planes.size();
        Timer build;
        Grid grid = buildGrid(scene, variant.grid);
        r.buildMs = build.elapsedMs();
        r.grid = variant.grid.mode == GridOptions::Mode::Off
                     ? "off"
                     : std::string(grid.adaptive() ? "adaptive " : "") +
                           std::to_string(grid.resolution.x) + "x" +
                           std::to_string(grid.resolution.y) + "x" +
                           std::to_string(grid.resolution.z);
        r.maxPerCell = grid.maxPerCell;
        r.gridBytes = grid.bytes();
        r.walk = countWalks(scene, grid, double(settings.width) / double(settings.height));
        TracerOptions options = variant.tracer;
        options.maxDepth = settings.maxDepth;
        auto tracer = std::make_unique<RayTracer>(context, scene, grid, settings.width,
                                                  settings.height, options);
        tracer->setSeed(settings.seed);
        for (const ArrayBytes &a : tracer->sceneArrayBytes())
            r.sceneBytes += a.bytes;
        FrameResult warm = tracer->renderFrame(scene.camera, settings.samplesPerPixel);
        r.rays = warm.rays;
        if (!settings.imageDir.empty())
            saveImage(context, *tracer, settings,
                      std::filesystem::path(settings.imageDir) /
                          (s.name + "_" + variant.name + ".exr"));
        s.results.push_back(r);
        s.tracers.push_back(std::move(tracer));
        if (settings.profile)
            s.grids.push_back(std::move(grid));
    }
    if (settings.embreeBaseline) {
        progress(s.name + " embree: build + warm-up");
        s.embree = std::make_unique<EmbreeBaseline>(s.source, settings.width, settings.height);
        BenchResult r;
        r.scene = s.name;
        r.variant = "embree";
        r.primitives = s.source.finitePrimitiveCount() + s.source.planes.size();
        r.grid = "BVH";
        r.buildMs = s.embree->build().commitMs;
        r.rays = s.embree->traceFrame().rays;
        s.results.push_back(r);
    }
    return study;
}

// Timed frame number `run` of every variant of the scene, then Embree's.
void timeRun(SceneStudy &s, uint32_t run, const BenchSettings &settings,
             const std::function<void(const std::string &)> &progress) {
    for (size_t v = 0; v < s.tracers.size(); ++v) {
        progress(s.name + " " + s.results[v].variant + ": frame " + std::to_string(run + 1) + "/" +
                 std::to_string(settings.runs));
        FrameResult f =
            s.tracers[v]->renderFrame(s.variantScenes[v]->camera, settings.samplesPerPixel);
        s.results[v].frameMs.push_back(f.gpuMs);
        s.results[v].wallMs.push_back(f.wallMs);
    }
    if (s.embree) {
        progress(s.name + " embree: frame " + std::to_string(run + 1) + "/" +
                 std::to_string(settings.runs));
        double ms = s.embree->traceFrame().ms;
        s.results.back().frameMs.push_back(ms);
        s.results.back().wallMs.push_back(ms);
    }
}

void profileScene(vk::Context &context, SceneStudy &s, const std::vector<BenchVariant> &variants,
                  const BenchSettings &settings,
                  const std::function<void(const std::string &)> &progress) {
    for (size_t v = 0; v < variants.size() && settings.profile; ++v) {
        progress(s.name + " " + variants[v].name + ": profile");
        s.results[v].profile =
            profileVariant(context, *s.variantScenes[v], s.grids[v], variants[v], settings);
    }
}

} // namespace

std::vector<BenchResult> runStudy(vk::Context &context, const std::vector<std::string> &scenes,
                                  const std::vector<BenchVariant> &variants,
                                  const BenchSettings &settings,
                                  const std::function<void(const std::string &)> &progress) {
    // Scene after scene, each freed before the next is loaded; or, interleaved, every scene
    // set up first and each run's frames taken across all of them in turn.
    std::vector<BenchResult> all;
    auto finish = [&](SceneStudy &s) {
        profileScene(context, s, variants, settings, progress);
        all.insert(all.end(), s.results.begin(), s.results.end());
    };
    if (!settings.interleaveScenes) {
        for (const std::string &path : scenes) {
            std::unique_ptr<SceneStudy> s = setUpScene(context, path, variants, settings, progress);
            for (uint32_t run = 0; run < settings.runs; ++run)
                timeRun(*s, run, settings, progress);
            finish(*s);
        }
        return all;
    }
    std::vector<std::unique_ptr<SceneStudy>> studies;
    for (const std::string &path : scenes)
        studies.push_back(setUpScene(context, path, variants, settings, progress));
    for (uint32_t run = 0; run < settings.runs; ++run)
        for (std::unique_ptr<SceneStudy> &s : studies)
            timeRun(*s, run, settings, progress);
    for (std::unique_ptr<SceneStudy> &s : studies)
        finish(*s);
    return all;
}

} // namespace prism
