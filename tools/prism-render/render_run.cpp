#include "render_run.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "accel/grid_cache.h"
#include "accel/walk_counts.h"
#include "cache/disk_cache.h"
#include "core/error.h"
#include "core/median.h"
#include "core/parallel_for.h"
#include "core/timer.h"
#include "frame_range.h"
#include "frame_sources.h"
#include "io/image_write_queue.h"
#include "io/image_writer.h"
#include "io/staged_file.h"
#include "progress_line.h"
#include "render_metadata.h"
#include "scene/camera_animation.h"
#include "scene/placement_animation.h"
#include "scene/scene_loader.h"
#include "scene/text_file.h"
#include "session/prepared_scene.h"
#include "session/render_stats.h"

namespace prism {

// "1m05s", "12s", "0.4s": how long a progress line says is left (progress_line.h).
std::string durationText(double seconds) {
    char text[32];
    if (seconds < 10.0)
        std::snprintf(text, sizeof text, "%.1fs", seconds);
    else if (seconds < 60.0)
        std::snprintf(text, sizeof text, "%.0fs", seconds);
    else if (seconds < 3600.0)
        std::snprintf(text, sizeof text, "%dm%02ds", int(seconds) / 60, int(seconds) % 60);
    else
        std::snprintf(text, sizeof text, "%dh%02dm", int(seconds) / 3600, int(seconds) / 60 % 60);
    return text;
}

namespace {

// One image of the run: a frame of the scene's animation and the file it goes to.
struct FrameJob {
    int frame = 1;
    std::filesystem::path output;
};

// The run's images: the still (frame 1 at -o), or each --frames frame at its name from the
// pattern; with --skip-existing, those whose file is not there yet.
std::vector<FrameJob> frameJobs(const RenderOptions &o, size_t &skipped) {
    std::vector<FrameJob> jobs;
    std::string pattern =
        o.tileCount > 0 ? tilePath(o.outputPath.string(), o.tileIndex) : o.outputPath.string();
    if (o.frames.empty())
        jobs.push_back({1, pattern});
    for (int frame : o.frames)
        jobs.push_back({frame, framePath(pattern, frame)});
    skipped = 0;
    if (o.skipExisting)
        std::erase_if(jobs, [&](const FrameJob &job) {
            bool exists = std::filesystem::exists(job.output);
            skipped += exists ? 1 : 0;
            return exists;
        });
    return jobs;
}

// What each frame of a range cost (--stats "per_frame").
struct FrameRecord {
    int frame = 0;
    std::string output;
    double traceMs = 0.0, wallMs = 0.0, readbackMs = 0.0, countMs = 0.0;
    double frameMs = 0.0; // on the host from the frame's start until its image was queued
    double moveMs = 0.0;  // keyed placements: the instance level rebuilt and the arrays uploaded
};

} // namespace

void runRender(const RenderOptions &o) {
    // Before the device's and OpenImageIO's libraries load on threads of their own.
    startParallelThreads();
    Timer process; // from here (the command line is parsed) to the last image on disk
    size_t skipped = 0;
    std::vector<FrameJob> jobs = frameJobs(o, skipped);
    if (jobs.empty()) {
        if (!o.quiet)
            std::fprintf(stderr, "prism-render: all %zu image%s exist already (--skip-existing)\n",
                         skipped, skipped == 1 ? "" : "s");
        return;
    }
    for (const FrameJob &job : jobs) // a bad -o fails now, not after the render
        checkCanStage(job.output);
    // Built grids and the device's pipeline cache are kept here between runs.
    std::optional<DiskCache> cache;
    if (!o.cacheDir.empty())
        cache.emplace(DiskCacheOptions{o.cacheDir});
    std::optional<ContextInBackground> context;
    if (o.backend == Backend::Vulkan)
        context.emplace(o, cache ? &*cache : nullptr);
    // OpenImageIO loads on a thread of its own (joined on return) once the device has started:
    // the dynamic loader takes one lock for a library's whole load, so its ~260 libraries loaded
    // beside the driver's would hold the device back (started at once, they are loaded leaves
    // first one by one and the lock is free between them, yet the context still took 126 ms
    // against 23 and a sphere's 64x48 image 174 ms against 158); after it, they load while the
    // scene loads or builds and the tracer's pipelines compile. Declared after `context`: joined
    // before it goes.
    std::jthread imageFiles([&context] {
        if (context)
            context->waitUntilMade();
        preloadImageFiles();
    });
    Timer loadTimer;
    ObjCacheUse objCache{cache ? &*cache : nullptr};
    Scene loaded = loadScene(o.scenePath, {}, &objCache);
    double loadMs = loadTimer.elapsedMs();
    // The camera samples of one whole image decide how much the grid's build does
    // (GridOptions::effort): not the tile's or crop's, nor the range's, so that a tile is the
    // whole image's pixels and a frame the same image alone or in a range, to the bit.
    GridOptions gridOptions = o.grid;
    gridOptions.cameraSamples = uint64_t(o.width) * o.height * o.samplesPerPixel;
    // Both backends trace the same camera-relative scene and its grid.
    PreparedScene prepared =
        prepareScene(std::move(loaded), gridOptions, cache ? &*cache : nullptr);
    // Each frame's camera; a frame whose spline leaves the keys' range (a camera without a view,
    // a placement out of float range) fails the run now, before any image is written.
    std::vector<Camera> cameras;
    for (const FrameJob &job : jobs) {
        try {
            cameras.push_back(cameraAt(prepared.scene, job.frame));
            for (const PlacementTrack &track : prepared.scene.placementTracks)
                placementAt(prepared.scene, track, job.frame);
        } catch (const Error &e) {
            throw Error(displayPath(o.scenePath) + ": " + e.what());
        }
    }
    // Keyed placements: the first frame's instances before the tracer uploads them.
    double firstMoveMs = 0.0;
    moveToFrame(prepared, jobs.front().frame, &firstMoveMs);
    // Both refer to `prepared`, which each frame's moveToFrame changes in place.
    const Scene &scene = prepared.scene;
    const Grid &grid = prepared.grid;
    double buildMs = prepared.buildMs + firstMoveMs;
    if (!o.quiet)
        for (const std::string &warning : scene.warnings)
            std::fprintf(stderr, "%s\n", warning.c_str());

    std::unique_ptr<FrameSource> source;
    VulkanFrameSource *vulkan = nullptr;
    if (o.backend == Backend::Cpu) {
        source = std::make_unique<CpuFrameSource>(o, scene);
    } else {
        auto made = std::make_unique<VulkanFrameSource>(
            o, scene, grid, prepared.extent ? &*prepared.extent : nullptr, *context,
            cameras.front());
        vulkan = made.get();
        source = std::move(made);
    }

    ImageWriteQueue writer;
    ProgressLine progress(!o.quiet);
    std::vector<FrameRecord> frames;
    std::vector<double> allFrameMs, allWallMs; // every timed frame of the run
    FrameOutcome last;
    WalkCounts walk;
    double framesMs = 0.0, readbackMs = 0.0, countMs = 0.0;
    bool range = !o.frames.empty();
    Timer rangeTimer;
    for (size_t i = 0; i < jobs.size(); ++i) {
        const FrameJob &job = jobs[i];
        Timer frameTimer;
        std::string label = "frame " + std::to_string(i + 1) + "/" + std::to_string(jobs.size());
        if (range)
            label += " (" + std::to_string(job.frame) + ")";
        std::string after; // the frames so far say how long the rest takes
        if (i > 0)
            after =
                ", " +
                durationText(rangeTimer.elapsedMs() / 1e3 / double(i) * double(jobs.size() - i)) +
                " left";
        // Moving instances: the grid's instance level again, the arrays uploaded again.
        Timer moveTimer;
        if (i > 0 && moveToFrame(prepared, job.frame))
            source->sceneMoved(scene, grid);
        double frameMoveMs = i > 0 ? moveTimer.elapsedMs() : 0.0;
        const Camera &camera = cameras[i];
        FrameOutcome out = source->render(camera, label, after, progress);
        // The frame's rate by the host's clock: what the user waits, on either backend.
        double frameWallMs = *std::min_element(out.wallMs.begin(), out.wallMs.end());
        progress.update(label, 1.0, after,
                        frameWallMs > 0.0 ? double(out.rays.total()) / (frameWallMs * 1e3) : 0.0);
        // The grid's work per primary ray, counted on the CPU for every image; counting stops
        // at 1,000 tests a ray (under 2M tests, tens of ms, at worst), giving lower bounds.
        Timer countTimer;
        walk = countWalks(scene, camera, grid, double(o.width) / double(o.height), 48, 1e3);
        double frameCountMs = countTimer.elapsedMs();

        double bestMs = *std::min_element(out.frameMs.begin(), out.frameMs.end());
        RenderRecord record;
        record.commandLine = o.commandLine;
        record.scenePath = o.scenePath.string();
        record.device = source->device();
        record.backend = o.backend == Backend::Cpu ? "cpu" : "vulkan";
        record.gridResolution =
            o.backend == Backend::Cpu ? std::string("none (brute force)") : gridText(grid);
        record.rays = out.rays;
        record.renderTimeMs = bestMs;
        record.renderTimeMedianMs = median(out.frameMs);
        record.gridBuildMs = buildMs;
        record.gridChoice = grid.choice;
        record.gridCells = grid.cellCount();
        record.gridBytes = grid.bytes();
        record.gridCellsPerPrimaryRay = walk.cellsPerRay;
        record.gridTestsPerPrimaryRay = walk.testsPerRay;
        record.mraysPerSecond = double(out.rays.total()) / (bestMs * 1e3);
        record.samplesPerPixel = o.samplesPerPixel;
        record.maxDepth = o.maxDepth;
        record.seed = o.seed;
        record.frame = range ? job.frame : -1;
        if (!o.region.empty())
            record.region = regionText(o.region);
        if (o.tileCount > 0)
            record.tile = std::to_string(o.tileIndex) + "/" + std::to_string(o.tileCount);
        out.image.exrCompression = o.exrCompression;
        writer.push(job.output, std::move(out.image), renderMetadata(record));

        allFrameMs.insert(allFrameMs.end(), out.frameMs.begin(), out.frameMs.end());
        allWallMs.insert(allWallMs.end(), out.wallMs.begin(), out.wallMs.end());
        framesMs += out.framesMs;
        readbackMs += out.readbackMs;
        countMs += frameCountMs;
        frames.push_back({job.frame, job.output.string(), bestMs,
                          *std::min_element(out.wallMs.begin(), out.wallMs.end()), out.readbackMs,
                          frameCountMs, frameTimer.elapsedMs(), frameMoveMs});
        last = std::move(out);
    }
    Timer writeWait;
    writer.finish();
    double writeWaitMs = writeWait.elapsedMs();
    progress.finish();
    // Read what was loaded before saving: a save makes the saved bytes the cache's own.
    uint64_t pipelineCacheLoaded = vulkan ? vulkan->pipelineCacheLoaded() : 0;
    uint64_t pipelineCacheSaved = vulkan ? vulkan->savePipelineCache() : 0;
    double processMs = process.elapsedMs();
    std::vector<double> writeMs = writer.writeMs();
    if (range && !o.quiet)
        std::fprintf(
            stderr, "prism-render: %zu frame%s in %s (%.0f ms a frame after the first)%s\n",
            jobs.size(), jobs.size() == 1 ? "" : "s", durationText(processMs / 1e3).c_str(),
            jobs.size() > 1 ? (rangeTimer.elapsedMs() + writeWaitMs - frames[0].frameMs) /
                                  double(jobs.size() - 1)
                            : frames[0].frameMs,
            skipped > 0 ? (", " + std::to_string(skipped) + " skipped: they exist").c_str() : "");

    if (o.stats) {
        double bestMs = *std::min_element(allFrameMs.begin(), allFrameMs.end());
        nlohmann::json stats = {
            {"scene", o.scenePath.string()},
            {"backend", o.backend == Backend::Cpu ? "cpu" : "vulkan"},
            {"device", source->device()},
            {"width", o.width},
            {"height", o.height},
            {"region", regionText(o.region.empty() ? wholeImage(o.width, o.height) : o.region)},
            {"spp", o.samplesPerPixel},
            {"depth", o.maxDepth},
            {"seed", o.seed},
            {"grid_cells_per_primary_ray", walk.cellsPerRay},
            {"grid_tests_per_primary_ray", walk.testsPerRay},
            {"grid_counts_stopped", walk.stopped},
            {"load_ms", loadMs},
            {"trace_ms", bestMs},
            {"trace_ms_median", median(allFrameMs)},
            // What a caller waits a frame (the host's share included): the GPU timestamps
            // leave out the host's per-frame work and the queue's own start and end.
            {"wall_ms", *std::min_element(allWallMs.begin(), allWallMs.end())},
            {"wall_ms_median", median(allWallMs)},
            {"frames", allFrameMs.size()},
            {"pipeline_cache",
             {{"loaded_bytes", pipelineCacheLoaded}, {"saved_bytes", pipelineCacheSaved}}}};
        stats.update(sceneStats(prepared));
        stats["obj_cache"] = objCacheStats(objCache);
        stats.update(frameStats(last.rays, bestMs, last.resumeDispatches));
        if (vulkan) {
            stats["tiles"] = tileStats(last.tiles);
            stats["scene_gpu_bytes"] = gpuBytesStats(vulkan->sceneArrays());
        }
        double writeTotalMs = 0.0;
        for (double ms : writeMs)
            writeTotalMs += ms;
        nlohmann::json phases = {{"load", loadMs}, {"build", buildMs}};
        if (vulkan)
            phases.update({{"context", vulkan->phases().contextMs},
                           {"context_made", vulkan->phases().contextMadeMs},
                           {"tracer", vulkan->phases().tracerMs},
                           {"compile", vulkan->phases().compileMs},
                           {"frames", framesMs},
                           {"readback", readbackMs}});
        // write: the images' writes, on their own thread (a range's overlap its next frames);
        // write_wait: what the run waited for them at its end.
        phases.update({{"count", countMs},
                       {"write", writeTotalMs},
                       {"write_wait", writeWaitMs},
                       {"total", processMs}});
        stats["phases_ms"] = phases;
        if (range) {
            nlohmann::json perFrame = nlohmann::json::array();
            for (size_t i = 0; i < frames.size(); ++i)
                perFrame.push_back({{"frame", frames[i].frame},
                                    {"output", frames[i].output},
                                    {"trace_ms", frames[i].traceMs},
                                    {"wall_ms", frames[i].wallMs},
                                    {"readback_ms", frames[i].readbackMs},
                                    {"count_ms", frames[i].countMs},
                                    {"move_ms", frames[i].moveMs},
                                    {"write_ms", i < writeMs.size() ? writeMs[i] : 0.0},
                                    {"frame_ms", frames[i].frameMs}});
            stats["per_frame"] = perFrame;
            stats["skipped"] = skipped;
        }
        std::printf("%s\n", stats.dump().c_str());
    }
}

} // namespace prism
