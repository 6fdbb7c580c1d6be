#include "render_run.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <future>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "accel/grid_cache.h"
#include "accel/walk_counts.h"
#include "cache/disk_cache.h"
#include "core/error.h"
#include "core/median.h"
#include "core/timer.h"
#include "io/image_writer.h"
#include "io/staged_file.h"
#include "progress_line.h"
#include "reference/reference_renderer.h"
#include "render/ray_tracer.h"
#include "render_metadata.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"
#include "tile_tint.h"
#include "vk/context.h"

namespace prism {
namespace {

// Where a Vulkan render's wall-clock time goes before and after the frames (--stats
// "phases_ms"), so start-up can be judged: docs/benchmarks.md has cold and warm figures.
struct VulkanPhases {
    double contextMs = 0.0;     // waiting for the instance, device and queues (made meanwhile)
    double contextMadeMs = 0.0; // making them, on their own thread while the scene loads
    double tracerMs = 0.0;      // scene arrays uploaded, pipeline created for the scene's variant
    double compileMs = 0.0;     // the untimed 8x8 dispatch: lavapipe compiles the shader there
    double framesMs = 0.0;      // every frame on the host's clock, waits included
    double readbackMs = 0.0;    // accumulation (and AOVs) copied back and divided
};

// What one backend produced: the image and the per-frame timings.
struct RenderOutcome {
    OutputImage image;
    std::vector<double> frameMs;         // timed frames only (after warm-up): GPU timestamps
    std::vector<double> wallMs;          // the same frames by the host's clock (FrameResult)
    RayCounts rays;                      // of one frame
    uint32_t resumeDispatches = 0;       // of the last frame, when traced resumably
    std::array<uint32_t, 3> tiles{};     // of the last frame: FrameResult::tiles
    std::vector<ArrayBytes> sceneArrays; // the scene on the device (Vulkan only)
    std::string device;
    uint64_t pipelineCacheLoaded = 0, pipelineCacheSaved = 0; // bytes (vk/pipeline_cache.h)
    VulkanPhases phases;
};

// The Vulkan instance and device, made on a thread of their own while the scene loads and its
// grid builds (they need nothing of the scene): 120-180 ms of lavapipe's start-up (loading
// the driver and LLVM) that no longer adds to the wait (issue 31).
class ContextInBackground {
public:
    ContextInBackground(const RenderOptions &o, const DiskCache *pipelineStore) {
        vk::ContextOptions options;
        options.validation = o.validation;
        options.deviceNameFilter = o.deviceFilter;
        options.pipelineStore = pipelineStore;
        made_ = std::async(std::launch::async, [options] {
            Timer timer;
            auto context = std::make_unique<vk::Context>(options);
            return std::pair{std::move(context), timer.elapsedMs()};
        });
    }
    // The context (rethrowing what its creation threw), and how long the caller waited for it.
    vk::Context &get(double &waitedMs, double &madeMs) {
        Timer wait;
        if (!context_) {
            auto [context, ms] = made_.get();
            context_ = std::move(context);
            madeMs = ms;
        }
        waitedMs = wait.elapsedMs();
        return *context_;
    }

private:
    std::future<std::pair<std::unique_ptr<vk::Context>, double>> made_;
    std::unique_ptr<vk::Context> context_;
};

RenderOutcome renderOnVulkan(const RenderOptions &o, const Scene &scene, const Grid &grid,
                             ContextInBackground &background) {
    RenderOutcome out;
    Timer phase;
    vk::Context &context = background.get(out.phases.contextMs, out.phases.contextMadeMs);

    TracerOptions tracerOptions;
    tracerOptions.maxDepth = o.maxDepth;
    tracerOptions.writeAov = o.aovDepth || o.aovNormal;
    phase.reset();
    RayTracer tracer(context, scene, grid, o.width, o.height, tracerOptions);
    out.phases.tracerMs = phase.elapsedMs();

    out.device = context.deviceName();
    out.sceneArrays = tracer.sceneArrayBytes();
    ProgressLine progress(!o.quiet);
    // lavapipe compiles the shader inside the first dispatch: one 8x8 tile takes that out of
    // the timed frames. Timing several frames (--repeat) also gets a warm-up frame, so that
    // they are alike (caches, clocks); a single render does not pay a second frame for that.
    phase.reset();
    tracer.compile(scene.camera);
    out.phases.compileMs = phase.elapsedMs();
    phase.reset();
    for (uint32_t frame = o.repeat > 1 ? 0 : 1; frame <= o.repeat; ++frame) {
        std::string label = frame == 0
                                ? "warm-up frame"
                                : "frame " + std::to_string(frame) + "/" + std::to_string(o.repeat);
        FrameResult result = tracer.renderFrame(scene.camera, frame == 0 ? 1u : o.samplesPerPixel,
                                                [&](double f) { progress.update(label, f); });
        // renderFrame traces a frame that overran lavapipe's loop limit again, resumably.
        out.resumeDispatches = result.resumeDispatches;
        out.tiles = result.tiles;
        if (frame > 0) {
            out.frameMs.push_back(result.gpuMs);
            out.wallMs.push_back(result.wallMs);
        }
        out.rays = result.rays;
    }
    progress.finish();
    out.phases.framesMs = phase.elapsedMs();
    phase.reset();
    TracedImage traced = tracer.readback(o.samplesPerPixel);
    out.phases.readbackMs = phase.elapsedMs();
    if (context.validationMessageCount() > 0)
        throw Error(std::to_string(context.validationMessageCount()) +
                    " Vulkan validation messages (printed above); refusing to write the image");
    out.pipelineCacheLoaded = context.pipelineCacheLoadedBytes();
    out.pipelineCacheSaved = context.savePipelineCache();
    out.image.width = int(traced.width);
    out.image.height = int(traced.height);
    out.image.rgba = std::move(traced.rgba);
    if (o.showTiles)
        tintTilesByClass(out.image.rgba, traced.width, traced.height, tracer.lastTileClasses());
    if (o.aovDepth)
        out.image.depth = std::move(traced.depth);
    if (o.aovNormal)
        out.image.normal = std::move(traced.normal);
    return out;
}

RenderOutcome renderOnCpu(const RenderOptions &o, const Scene &scene) {
    RenderSettings settings;
    settings.width = int(o.width);
    settings.height = int(o.height);
    settings.samplesPerPixel = o.samplesPerPixel;
    settings.maxDepth = o.maxDepth;
    RenderOutcome out;
    out.device = "CPU reference (double precision)";
    ProgressLine progress(!o.quiet);
    RenderedImage rendered;
    for (uint32_t frame = 1; frame <= o.repeat; ++frame) {
        std::string label = "frame " + std::to_string(frame) + "/" + std::to_string(o.repeat);
        Timer timer;
        rendered = renderReference(scene, settings, [&](double f) { progress.update(label, f); });
        out.frameMs.push_back(timer.elapsedMs());
        out.wallMs.push_back(out.frameMs.back());
    }
    progress.finish();
    out.rays = rendered.rays;
    out.image.width = rendered.width;
    out.image.height = rendered.height;
    out.image.rgba.reserve(rendered.rgba.size() * 4);
    for (const glm::vec4 &p : rendered.rgba)
        out.image.rgba.insert(out.image.rgba.end(), {p.r, p.g, p.b, p.a});
    if (o.aovDepth)
        out.image.depth = rendered.depth;
    if (o.aovNormal)
        for (const glm::vec3 &n : rendered.normal)
            out.image.normal.insert(out.image.normal.end(), {n.x, n.y, n.z});
    return out;
}

} // namespace

void runRender(const RenderOptions &o) {
    Timer process;               // from here (the command line is parsed) to the image on disk
    checkCanStage(o.outputPath); // a bad -o fails now, not after the render
    // Built grids and the device's pipeline cache are kept here between runs.
    std::optional<DiskCache> cache;
    if (!o.noCache && !o.cacheDir.empty())
        cache.emplace(DiskCacheOptions{o.cacheDir});
    std::optional<ContextInBackground> context;
    if (o.backend == Backend::Vulkan)
        context.emplace(o, cache ? &*cache : nullptr);
    Timer loadTimer;
    Scene scene = loadScene(o.scenePath);
    centerOnCamera(scene); // both backends trace the same camera-relative scene
    double loadMs = loadTimer.elapsedMs();
    if (!o.quiet)
        for (const std::string &warning : scene.warnings)
            std::fprintf(stderr, "%s\n", warning.c_str());

    Timer buildTimer;
    GridCacheOutcome cacheOutcome;
    Grid grid =
        buildGridCached(scene, o.grid, GridCachePolicy{cache ? &*cache : nullptr}, &cacheOutcome);
    double buildMs = buildTimer.elapsedMs();

    RenderOutcome out = o.backend == Backend::Cpu ? renderOnCpu(o, scene)
                                                  : renderOnVulkan(o, scene, grid, *context);
    double bestMs = *std::min_element(out.frameMs.begin(), out.frameMs.end());
    double medianMs = median(out.frameMs);
    double mraysPerSecond = double(out.rays.total()) / (bestMs * 1e3);

    RenderRecord record;
    record.commandLine = o.commandLine;
    record.scenePath = o.scenePath.string();
    record.device = out.device;
    record.backend = o.backend == Backend::Cpu ? "cpu" : "vulkan";
    record.gridResolution =
        o.backend == Backend::Cpu ? std::string("none (brute force)") : gridText(grid);
    record.rays = out.rays;
    record.renderTimeMs = bestMs;
    record.renderTimeMedianMs = medianMs;
    record.gridBuildMs = buildMs;
    // The grid's work per primary ray, counted on the CPU for every render; counting stops at
    // 1,000 tests a ray (under 2M tests, tens of ms, at worst), giving lower bounds.
    Timer countTimer;
    WalkCounts walk = countWalks(scene, grid, double(o.width) / double(o.height), 48, 1e3);
    double countMs = countTimer.elapsedMs();
    record.gridChoice = grid.choice;
    record.gridCells = grid.cellCount();
    record.gridBytes = grid.bytes();
    record.gridCellsPerPrimaryRay = walk.cellsPerRay;
    record.gridTestsPerPrimaryRay = walk.testsPerRay;
    record.mraysPerSecond = mraysPerSecond;
    record.samplesPerPixel = o.samplesPerPixel;
    record.maxDepth = o.maxDepth;
    ImageMetadata meta = renderMetadata(record);
    Timer writeTimer;
    writeImage(o.outputPath, out.image, meta);
    double writeMs = writeTimer.elapsedMs();
    double processMs = process.elapsedMs();

    if (o.stats) {
        nlohmann::json stats = {
            {"scene", o.scenePath.string()},
            {"backend", o.backend == Backend::Cpu ? "cpu" : "vulkan"},
            {"device", out.device},
            {"width", o.width},
            {"height", o.height},
            {"spp", o.samplesPerPixel},
            {"depth", o.maxDepth},
            {"primitives", scene.finitePrimitiveCount() + scene.planes.size()},
            {"grid", gridText(grid)},
            {"grid_cells", grid.cellCount()},
            {"grid_bytes", grid.bytes()},
            {"grid_mean_per_cell",
             double(grid.cellPrimitives.size()) / double(std::max<uint64_t>(1, grid.cellCount()))},
            {"grid_max_per_cell", grid.maxPerCell},
            {"grid_choice", grid.choice},
            {"grid_cells_per_primary_ray", walk.cellsPerRay},
            {"grid_tests_per_primary_ray", walk.testsPerRay},
            {"grid_counts_stopped", walk.stopped},
            {"load_ms", loadMs},
            {"build_ms", buildMs},
            {"trace_ms", bestMs},
            {"trace_ms_median", medianMs},
            // What a caller waits a frame (the host's share included): the GPU timestamps
            // leave out the host's per-frame work and the queue's own start and end.
            {"wall_ms", *std::min_element(out.wallMs.begin(), out.wallMs.end())},
            {"wall_ms_median", median(out.wallMs)},
            {"frames", out.frameMs.size()},
            {"rays",
             {{"primary", out.rays.primary},
              {"shadow", out.rays.shadow},
              {"secondary", out.rays.secondary}}},
            {"mrays_per_s", mraysPerSecond},
            {"resume_dispatches", out.resumeDispatches},
            {"grid_cache",
             {{"state", cacheOutcome.state},
              {"key_ms", cacheOutcome.keyMs},
              {"read_ms", cacheOutcome.readMs},
              {"store_ms", cacheOutcome.storeMs}}},
            {"pipeline_cache",
             {{"loaded_bytes", out.pipelineCacheLoaded}, {"saved_bytes", out.pipelineCacheSaved}}}};
        if (o.backend == Backend::Vulkan) // which tracer ran each 8x8 tile (render/traced_tiles.h)
            stats["tiles"] = {{"full", out.tiles[0]},
                              {"planes_only", out.tiles[1]},
                              {"background", out.tiles[2]}};
        // Instances: the triangles stored (the scene's and each prototype's once) against the
        // triangles the placements draw.
        uint64_t placedTriangles = 0;
        for (const Instance &i : scene.instances)
            placedTriangles += scene.prototypes[i.prototype].triangles.size();
        stats["triangles"] = {{"scene", scene.triangles.size()},
                              {"prototypes", scene.prototypeTriangleCount()},
                              {"instances", scene.instances.size()},
                              {"placed", placedTriangles}};
        if (!out.sceneArrays.empty()) {
            nlohmann::json gpuBytes;
            uint64_t total = 0;
            for (const ArrayBytes &a : out.sceneArrays) {
                gpuBytes[a.what] = a.bytes;
                total += a.bytes;
            }
            gpuBytes["total"] = total;
            stats["scene_gpu_bytes"] = gpuBytes;
        }
        nlohmann::json phases = {{"load", loadMs}, {"build", buildMs}};
        if (o.backend == Backend::Vulkan)
            phases.update({{"context", out.phases.contextMs},
                           {"context_made", out.phases.contextMadeMs},
                           {"tracer", out.phases.tracerMs},
                           {"compile", out.phases.compileMs},
                           {"frames", out.phases.framesMs},
                           {"readback", out.phases.readbackMs}});
        phases.update({{"count", countMs}, {"write", writeMs}, {"total", processMs}});
        stats["phases_ms"] = phases;
        std::printf("%s\n", stats.dump().c_str());
    }
}

} // namespace prism
