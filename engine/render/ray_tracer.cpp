#include "render/ray_tracer.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/parallel_for.h"
#include "core/timer.h"
#include "render/frame_params.h"
#include "render/lavapipe_threads.h"
#include "render/plane_shadows.h"
#include "shaders/trace.comp.spv.h"
#include "shaders/trace_background.comp.spv.h"
#include "shaders/trace_planes.comp.spv.h"
#include "shaders/trace_profile.comp.spv.h"
#include "shared/trace_interface.h"
#include "vk/barriers.h"

namespace prism {
namespace {

ArrayLimits arrayLimits(const vk::Context &context, const TracerOptions &options) {
    const VkPhysicalDeviceLimits &device = context.properties().limits;
    ArrayLimits limits;
    limits.storageBytes = device.maxStorageBufferRange;
    if (options.storageBufferLimit != 0)
        limits.storageBytes = std::min<uint64_t>(limits.storageBytes, options.storageBufferLimit);
    limits.texelElements = device.maxTexelBufferElements;
    limits.texelReads = options.texelBuffers;
    return limits;
}

} // namespace

RayTracer::RayTracer(vk::Context &context, const Scene &scene, const Grid &grid, uint32_t width,
                     uint32_t height, const TracerOptions &options)
    : context_(context), options_(options),
      features_(
          chooseFeatures(scene, grid, options, context.properties().limits.maxTexelBufferElements)),
      limits_(arrayLimits(context, options)), runner_(context),
      stats_(context, sizeof(gpu::GpuStats),
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT, // snapshots for the viewer
             true),
      planeCount_(uint32_t(scene.planes.size())), lightCount_(uint32_t(scene.lights.size())),
      resumeMemoryBytes_(options.resumeMemoryBytes),
      resumeRecords_(context, 32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false),
      walkLog_(context, 32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false), timestamps_(context) {
    if (features_.profile > 0 && !context.shaderClockEnabled())
        throw Error("profiling needs a Vulkan context created with the shader clock");
    region_ = options.region.empty() ? wholeImage(width, height) : options.region;
    checkPixelBounds(region_, width, height);
    auto writeArrays = [&] {
        scene_ = uploadScene(
            context, runner_,
            packScene(scene, grid, features_.cellTriangles, features_.cellSpheres), limits_,
            options.stagedUpload ? UploadPath::Staged : UploadPath::InPlaceWhereShared);
        extent_ = options.extent && options.maxStartBoxes == kMaxStartBoxes
                      ? *options.extent
                      : sceneExtent(scene, grid, options.maxStartBoxes);
    };
    if (scene.finitePrimitiveCount() >= options.compileBesideUploadFrom) {
        compileBeside(writeArrays);
    } else {
        writeArrays();
        pipeline_ = compileTracerPipeline(features_, Module::Full);
    }
    createImages(width, height);
    bindTracerPipeline(*pipeline_);
    if (options.cullMissTiles)
        missPipeline_ = createTracerPipeline(features_.backgroundOnly(), Module::BackgroundOnly);
    tileStarts_ = options.cullMissTiles && options.tileStarts;
    // A GPU schedules workgroups its own way: there the order of the rows does not matter.
    dispatchShares_ = context.isLavapipe() && options.rowsByThread ? lavapipeDispatchShares() : 0;
    choosePlaneGuards(scene);
    options_.extent = nullptr; // the caller's, for this constructor only: setScene finds its own
}

// A big scene's tracer pipeline compiles on one core while the scene's arrays are written and its
// extent found on the other: on lavapipe each takes 100-200 ms for a 1M-triangle mesh, one after
// the other before (issue 31, docs/benchmarks.md). Both run on parallelFor's kept threads, the
// writers' own loops held to their thread meanwhile: a thread started now could wait for the
// dynamic loader's lock while OpenImageIO loads (core/parallel_for.h, startParallelThreads).
// The first failure of either is rethrown once both are done.
void RayTracer::compileBeside(const std::function<void()> &writeArrays) {
    std::unique_ptr<vk::ComputePipeline> compiled;
    std::exception_ptr failures[2];
    std::atomic<int> next{0};
    auto part = [&] {
        int mine = next++;
        try {
            if (mine == 0) {
                compiled = compileTracerPipeline(features_, Module::Full);
            } else {
                ParallelThreadsHere alone(1);
                writeArrays();
            }
        } catch (...) {
            failures[mine] = std::current_exception();
        }
    };
    runOnWorkerPool(1, part);
    while (next < 2) // the pool was busy, or had no thread to give: the rest on this one
        part();
    for (const std::exception_ptr &failure : failures)
        if (failure)
            std::rethrow_exception(failure);
    pipeline_ = std::move(compiled);
}

void RayTracer::choosePlaneGuards(const Scene &scene) {
    planeGuards_.reset();
    size_t mirror = 0;
    PlaneTiles mode = planeTilesMode(scene, mirror);
    if (options_.cullMissTiles && options_.cullPlaneTiles && mode != PlaneTiles::Never)
        planeGuards_ = planeTileGuards(
            extent_.boxes, extent_.planes, scene.lights, features_.shadows,
            mode == PlaneTiles::OneMirror ? std::optional<size_t>(mirror) : std::nullopt);
}

void RayTracer::setScene(const Scene &scene, const Grid &grid) {
    vkDeviceWaitIdle(context_.device()); // no submission may still read the old arrays
    TracerFeatures features =
        chooseFeatures(scene, grid, options_, context_.properties().limits.maxTexelBufferElements);
    features.resumable = features_.resumable; // once switched, for good
    scene_ = uploadScene(
        context_, runner_, packScene(scene, grid, features.cellTriangles, features.cellSpheres),
        limits_, options_.stagedUpload ? UploadPath::Staged : UploadPath::InPlaceWhereShared);
    if (features == features_) {
        // The same variants read the new arrays: no compile.
        for (vk::ComputePipeline *pipeline :
             {pipeline_.get(), missPipeline_.get(), planesPipeline_.get()})
            if (pipeline)
                bindScene(*pipeline, scene_, limits_);
    } else {
        features_ = features;
        createPipeline();
        if (missPipeline_)
            missPipeline_ =
                createTracerPipeline(features_.backgroundOnly(), Module::BackgroundOnly);
        planesPipeline_.reset();
    }
    extent_ = sceneExtent(scene, grid, options_.maxStartBoxes);
    choosePlaneGuards(scene);
    keptTiles_.params.reset(); // the tile lists follow the scene's boxes too
}

vk::ComputePipeline &RayTracer::planesPipeline() {
    // Made when a view first has such tiles: many scenes' views have none (shadows over every
    // plane tile, a camera inside a box of walls), and the pipeline costs tens of milliseconds.
    if (!planesPipeline_)
        planesPipeline_ = createTracerPipeline(
            features_.planesOnly(planeGuards_->mirror.has_value()), Module::PlanesOnly);
    return *planesPipeline_;
}

RayTracer::PlaneTiles RayTracer::planeTilesMode(const Scene &scene, size_t &mirror) const {
    // Resumable tracing dispatches tile by tile, with one pipeline.
    if (features_.resumable || extent_.boxes.empty() || extent_.planes.empty())
        return PlaneTiles::Never;
    // The variant has no grid for any ray: a plane hit must start no secondary ray that could
    // reach the grid.
    if (features_.maxDepth == 1)
        return PlaneTiles::NoSecondaryRays;
    auto reflects = [&](const Plane &p) {
        return features_.reflection && scene.materials[p.material].reflect > 0.0f;
    };
    auto refracts = [&](const Plane &p) {
        return features_.transmission && scene.materials[p.material].transmit > 0.0f;
    };
    if (std::any_of(scene.planes.begin(), scene.planes.end(), refracts))
        return PlaneTiles::Never;
    std::vector<size_t> mirrors;
    for (size_t i = 0; i < scene.planes.size(); ++i)
        if (reflects(scene.planes[i]))
            mirrors.push_back(i);
    if (mirrors.empty())
        return PlaneTiles::NoSecondaryRays;
    // One mirror among matte planes (the seed scenes' reflective floors and plain walls): its
    // reflections are followed as mirror images (planeMirrorBoxes). Not where maps bend its
    // normal, nor where a reflection could meet a second mirror.
    mirror = mirrors[0];
    if (mirrors.size() == 1 && !scene.materials[scene.planes[mirror].material].hasSurfaceMaps())
        return PlaneTiles::OneMirror;
    return PlaneTiles::Never;
}

void RayTracer::createPipeline() {
    pipeline_ = createTracerPipeline(features_, Module::Full);
}

std::unique_ptr<vk::ComputePipeline> RayTracer::createTracerPipeline(const TracerFeatures &features,
                                                                     Module module) {
    std::unique_ptr<vk::ComputePipeline> pipeline = compileTracerPipeline(features, module);
    bindTracerPipeline(*pipeline);
    return pipeline;
}

std::unique_ptr<vk::ComputePipeline>
RayTracer::compileTracerPipeline(const TracerFeatures &features, Module module) const {
    vk::ComputePipelineDesc desc;
    // The profiling build times background tiles too, with the full module (no kinds).
    if (features.profile > 0)
        desc.spirv =
            std::span<const uint32_t>(kTraceProfileCompSpv, sizeof(kTraceProfileCompSpv) / 4);
    else if (module == Module::PlanesOnly)
        desc.spirv =
            std::span<const uint32_t>(kTracePlanesCompSpv, sizeof(kTracePlanesCompSpv) / 4);
    else if (module == Module::BackgroundOnly)
        desc.spirv =
            std::span<const uint32_t>(kTraceBackgroundCompSpv, sizeof(kTraceBackgroundCompSpv) / 4);
    else
        desc.spirv = std::span<const uint32_t>(kTraceCompSpv, sizeof(kTraceCompSpv) / 4);
    desc.bindings = traceDescriptorTypes();
    desc.specialization = features.specialization();
    desc.pushConstantBytes = sizeof(gpu::GpuFrameParams);
    // The background-only module is small enough that folding would cost more (6 ms) than the
    // driver saves (2-3 ms).
    desc.foldSpecialization = options_.foldSpecialization && module != Module::BackgroundOnly;
    return std::make_unique<vk::ComputePipeline>(context_, desc);
}

void RayTracer::bindTracerPipeline(vk::ComputePipeline &pipeline) {
    bindImages(pipeline);
    bindScene(pipeline, scene_, limits_);
    pipeline.bindBuffer(gpu::kBindingStats, stats_.handle());
    pipeline.bindBuffer(gpu::kBindingResumeRecords, resumeRecords_.handle());
    pipeline.bindBuffer(gpu::kBindingWalkLog, walkLog_.handle());
}

void RayTracer::bindImages(vk::ComputePipeline &pipeline) {
    pipeline.bindStorageImage(gpu::kBindingAccumImage, accum_.view());
    pipeline.bindStorageImage(gpu::kBindingAovImage, aov_.view());
    pipeline.bindTexelBuffer(gpu::kBindingTileList, tileListView_.handle());
}

void RayTracer::resize(uint32_t width, uint32_t height) {
    copiedOut_ = false;
    vkDeviceWaitIdle(context_.device()); // no submission may still use the old images
    keptTiles_.params.reset();           // defensive: the new size's parameters differ anyway
    region_ = wholeImage(width, height);
    createImages(width, height);
    bindImages(*pipeline_);
    if (missPipeline_)
        bindImages(*missPipeline_);
    if (planesPipeline_)
        bindImages(*planesPipeline_);
    if (resumePlan_.tileWidth != 0) // tiles and logs are planned for the image size
        startResuming();
}

void RayTracer::recordResetCounters(VkCommandBuffer commands) {
    vkCmdFillBuffer(commands, stats_.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void RayTracer::recordCounterSnapshot(VkCommandBuffer commands, VkBuffer target) const {
    vk::memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferCopy region{0, 0, sizeof(gpu::GpuStats)};
    vkCmdCopyBuffer(commands, stats_.handle(), target, 1, &region);
    // Also orders the next frame's counter updates after this read.
    vk::memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_HOST_READ_BIT);
}

VkDeviceSize RayTracer::counterBytes() {
    return sizeof(gpu::GpuStats);
}

FrameResult RayTracer::decodeCounters(const void *snapshot) {
    gpu::GpuStats stats;
    std::memcpy(&stats, snapshot, sizeof(stats));
    FrameResult result;
    for (const gpu::GpuRayCounts &slot : stats.rayCounts) {
        result.rays.primary += slot.primary;
        result.rays.shadow += slot.shadow;
        result.rays.secondary += slot.secondary;
        result.loopCutPixels += slot.loopCut;
    }
    std::copy(std::begin(stats.phaseNs), std::end(stats.phaseNs), result.phaseNs.begin());
    return result;
}

RayTracer::~RayTracer() {
    vkDeviceWaitIdle(context_.device());
}

void RayTracer::createImages(uint32_t width, uint32_t height) {
    width_ = width;
    height_ = height;
    window_ = tilesCovering(region_.x0, region_.y0, region_.x1, region_.y1);
    storeWidth_ = std::min(window_.x1 * kTileSize, width) - window_.x0 * kTileSize;
    storeHeight_ = std::min(window_.y1 * kTileSize, height) - window_.y0 * kTileSize;
    VkImageUsageFlags usage =
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    // On a CPU device the host reads the images where the tracer wrote them: the copy to a
    // buffer was a quarter of what a 320x240 view of the bunny spent outside its trace (0.25 ms
    // of a 10 ms frame, a loop of views from Python). Device memory is the host's there, and
    // lavapipe's images are linear whatever their tiling, so the trace is no slower. A GPU
    // keeps its images in its own memory and copies them out.
    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    inPlaceReadback_ =
        !options_.copiedReadback &&
        context_.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU &&
        vk::Image::hostReadableSupported(context_, storeWidth_, storeHeight_, format, usage);
    accum_ = vk::Image(context_, storeWidth_, storeHeight_, format, usage, inPlaceReadback_);
    // Every tile row by row, for the full tracer: what compile()'s one-tile dispatches read.
    TileRect tiles = imageTiles(width, height);
    VkDeviceSize listBytes =
        VkDeviceSize(window_.width()) * window_.height() * 2 * sizeof(uint32_t);
    tileList_ = vk::Buffer(
        context_, listBytes,
        VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    tileListView_ = vk::BufferView(context_, tileList_.handle(), VK_FORMAT_R32G32_UINT, listBytes);
    runner_.run(
        [&](VkCommandBuffer commands) { recordTileList(commands, allTiles(tiles, window_)); });
    // The AOV image is full size only when asked for: a scene pays for what it uses.
    bool aov = features_.writeAov;
    aov_ = vk::Image(context_, aov ? storeWidth_ : 1, aov ? storeHeight_ : 1, format, usage,
                     inPlaceReadback_);
    runner_.run([&](VkCommandBuffer commands) {
        for (const vk::Image *image : {&accum_, &aov_})
            vk::imageBarrier(commands, image->handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                             VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    });
}

void RayTracer::recordSamples(VkCommandBuffer commands, const Camera &camera, uint32_t firstSample,
                              uint32_t count, uint32_t samplesPerPixel) {
    gpu::GpuFrameParams params = frameParams(camera, samplesPerPixel);
    // The same camera for every sample: which tiles may hit something is found once, and kept
    // for the next call while the camera rests (the viewer's progressive samples).
    recordSamples(commands, params, frameTiles(params, true), firstSample, count);
}

void RayTracer::recordSamples(VkCommandBuffer commands, gpu::GpuFrameParams params,
                              const TileLists &lists, uint32_t firstSample, uint32_t count) {
    copiedOut_ = false;
    recordTileList(commands, lists);
    for (uint32_t s = firstSample; s < firstSample + count; ++s) {
        setFrameSample(params, s);
        recordSample(commands, params, lists);
    }
}

gpu::GpuFrameParams RayTracer::frameParams(const Camera &camera, uint32_t samplesPerPixel) const {
    gpu::GpuFrameParams params =
        makeFrameParams(camera, width_, height_, samplesPerPixel, features_.maxDepth);
    params.seedsAndLoops.z = planeCount_;
    params.seedsAndLoops.w = lightCount_;
    params.forward.w = float(seed_);             // frameSeed
    params.du.w = float(window_.x0 * kTileSize); // frameStoreOrigin
    params.dv.w = float(window_.y0 * kTileSize);
    return params;
}

void RayTracer::setSeed(uint32_t seed) {
    if (seed > gpu::kMaxSeed)
        throw Error("the sampling seed is 0 to " + std::to_string(gpu::kMaxSeed) + ", got " +
                    std::to_string(seed));
    seed_ = seed;
}

std::vector<uint8_t> RayTracer::frameTileClasses(const gpu::GpuFrameParams &params,
                                                 const std::vector<float> *starts) const {
    TileRect image = imageTiles(width_, height_);
    if (!missPipeline_)
        return std::vector<uint8_t>(size_t(image.width()) * image.height(), kTileFull);
    if (planeGuards_)
        return tileClasses(params, extent_, needGridBoxes(*planeGuards_, params), starts);
    return tilesThatMayHit(params, extent_, starts);
}

const TileLists &RayTracer::frameTiles(const gpu::GpuFrameParams &params, bool reuse) {
    // Projecting the blocks takes 1-2 ms of the host's time here: more than a sample of a
    // small scene on a fast GPU. The viewer records one sample a frame while the camera rests,
    // with the same parameters every time (the sample index is set later, on a copy).
    KeptTiles &kept = keptTiles_;
    if (!reuse || !kept.params || std::memcmp(&*kept.params, &params, sizeof(params)) != 0) {
        kept.params.reset(); // nothing half made is ever taken for the new parameters' lists
        std::vector<float> starts;
        if (tileStarts_)
            starts = tileStartDistances(params, extent_.startBoxes);
        kept.classes = frameTileClasses(params, tileStarts_ ? &starts : nullptr);
        kept.lists =
            tileLists(kept.classes, imageTiles(width_, height_), starts, dispatchShares_, window_);
        kept.params = params;
        ++kept.made;
    }
    lastTileClasses_ = kept.classes;
    return kept.lists;
}

void RayTracer::recordTileList(VkCommandBuffer commands, const TileLists &lists) {
    // Earlier dispatches (of this or an earlier submission) have read the old list.
    vk::memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    // Each entry: the tile, and its start distance's bits (0: from the eye).
    std::vector<uint32_t> entries(2 * lists.tiles.size(), 0);
    for (size_t i = 0; i < lists.tiles.size(); ++i) {
        entries[2 * i] = lists.tiles[i];
        if (i < lists.starts.size())
            std::memcpy(&entries[2 * i + 1], &lists.starts[i], sizeof(float));
    }
    // vkCmdUpdateBuffer takes at most 65,536 bytes a call.
    const size_t chunk = 65536 / sizeof(uint32_t);
    for (size_t first = 0; first < entries.size(); first += chunk) {
        size_t count = std::min(chunk, entries.size() - first);
        vkCmdUpdateBuffer(commands, tileList_.handle(), first * sizeof(uint32_t),
                          count * sizeof(uint32_t), entries.data() + first);
    }
    vk::memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

void RayTracer::recordSample(VkCommandBuffer commands, const gpu::GpuFrameParams &params,
                             const TileLists &lists) {
    uint32_t total = uint32_t(lists.tiles.size());
    recordTiles(commands, *pipeline_, params, 0, lists.full);
    if (lists.traced > lists.full) // only where planeGuards_
        recordTiles(commands, planesPipeline(), params, lists.full, lists.traced - lists.full);
    if (missPipeline_)
        recordTiles(commands, *missPipeline_, params, lists.traced, total - lists.traced);
    recordAccumulationBarrier(commands); // the tiles of one sample do not overlap
}

void RayTracer::recordTiles(VkCommandBuffer commands, const vk::ComputePipeline &pipeline,
                            gpu::GpuFrameParams params, uint32_t first, uint32_t count) {
    if (count == 0)
        return;
    params.control.z = first;
    params.control.w = first + count;
    // Rows of at most 65,535 workgroups (maxComputeWorkGroupCount is only guaranteed to be
    // that a dimension, and a 2048x2048 image has 65,536 tiles), as even as they can be: the
    // shader finds its entry from its place in the dispatch, and the few workgroups past the
    // range leave at once (on lavapipe they still run the shader, masked).
    uint32_t groupsY = (count + 65534u) / 65535u, groupsX = (count + groupsY - 1) / groupsY;
    pipeline.bind(commands);
    vkCmdPushConstants(commands, pipeline.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(params),
                       &params);
    vkCmdDispatch(commands, groupsX, groupsY, 1);
}

void RayTracer::recordDispatch(VkCommandBuffer commands, const gpu::GpuFrameParams &params,
                               uint32_t groupsX, uint32_t groupsY) {
    vkCmdPushConstants(commands, pipeline_->layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                       sizeof(params), &params);
    vkCmdDispatch(commands, groupsX, groupsY, 1);
    recordAccumulationBarrier(commands);
}

void RayTracer::recordAccumulationBarrier(VkCommandBuffer commands) {
    // Each sample reads the sum the previous one wrote.
    vk::imageBarrier(commands, accum_.handle(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void RayTracer::compile(const Camera &camera) {
    copiedOut_ = false;
    gpu::GpuFrameParams params = frameParams(camera, 1);
    const TileLists &lists = frameTiles(params, false);
    runner_.run([&](VkCommandBuffer commands) {
        recordTiles(commands, *pipeline_, params, 0, 1);
        recordAccumulationBarrier(commands);
        // lavapipe compiles each variant at its first dispatch (the tracer of planes only where
        // this view has tiles for it).
        if (lists.traced > lists.full) {
            recordTiles(commands, planesPipeline(), params, 0, 1);
            recordAccumulationBarrier(commands);
        }
        if (missPipeline_) {
            recordTiles(commands, *missPipeline_, params, 0, 1);
            recordAccumulationBarrier(commands);
        }
    });
}

FrameResult RayTracer::renderFrame(const Camera &camera, uint32_t samplesPerPixel,
                                   const std::function<void(double)> &progress, bool copyOut) {
    if (features_.resumable)
        return renderResumable(camera, samplesPerPixel, progress);
    FrameResult result;
    uint32_t chunks = progress ? std::min(samplesPerPixel, 20u) : 1u;
    uint32_t done = 0;
    // The tile lists once a frame, however many submissions its samples take, and made anew
    // for every frame: a frame is timed as a moving camera's would be (benchmarks repeat one).
    Timer listTimer;
    gpu::GpuFrameParams params = frameParams(camera, samplesPerPixel);
    const TileLists &lists = frameTiles(params, false);
    result.wallMs += listTimer.elapsedMs();
    for (uint32_t chunk = 0; chunk < chunks; ++chunk) {
        uint32_t end = uint32_t(uint64_t(samplesPerPixel) * (chunk + 1) / chunks);
        Timer hostTimer;
        runner_.run([&](VkCommandBuffer commands) {
            timestamps_.recordReset(commands);
            if (chunk == 0)
                recordResetCounters(commands);
            timestamps_.recordStart(commands);
            recordSamples(commands, params, lists, done, end - done);
            timestamps_.recordEnd(commands);
            vk::memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                              VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                              VK_ACCESS_HOST_READ_BIT);
            // After the timestamps: not part of the trace's time. An image read in place needs
            // only the barrier above.
            if (copyOut && chunk + 1 == chunks && !inPlaceReadback_)
                recordCopyOut(commands);
        });
        double hostMs = hostTimer.elapsedMs();
        result.gpuMs += timestamps_.elapsedMs().value_or(hostMs);
        result.wallMs += hostMs;
        done = end;
        if (progress)
            progress(double(done) / samplesPerPixel);
    }
    FrameResult counted = decodeCounters(stats_.mapped());
    result.rays = counted.rays;
    result.loopCutPixels = counted.loopCutPixels;
    result.phaseNs = counted.phaseNs;
    // Counted from the lists the frame was traced with (FrameResult::tiles' order).
    result.tiles = {lists.full, lists.traced - lists.full,
                    uint32_t(lists.tiles.size()) - lists.traced};
    copiedOut_ = copyOut || inPlaceReadback_; // the frame's last barrier made it readable
    if (result.loopCutPixels > 0) {
        FrameResult resumed = renderResumable(camera, samplesPerPixel, progress); // switches
        resumed.gpuMs += result.gpuMs; // the frame's time includes the pass that was cut
        resumed.wallMs += result.wallMs;
        resumed.loopCutPixels = 0;
        return resumed;
    }
    return result;
}

void RayTracer::recordCopyOut(VkCommandBuffer commands) {
    // Read in place, the images only need the shader's writes made visible to the host (after
    // a recording other than renderFrame's: compile, recordSamples, a resumable frame).
    if (inPlaceReadback_) {
        vk::memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                          VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                          VK_ACCESS_HOST_READ_BIT);
        return;
    }
    VkDeviceSize bytes = VkDeviceSize(region_.width()) * region_.height() * 16;
    auto kept = [&](vk::Buffer &buffer, VkDeviceSize size) -> const vk::Buffer & {
        if (buffer.size() != size) // the first readback, or another size since (resize)
            buffer = vk::Buffer(context_, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
        return buffer;
    };
    const vk::Buffer &colour = kept(readbackColour_, bytes);
    const vk::Buffer &aov = kept(readbackAov_, features_.writeAov ? bytes : 16);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageOffset = {int32_t(region_.x0 - window_.x0 * kTileSize),
                          int32_t(region_.y0 - window_.y0 * kTileSize), 0};
    region.imageExtent = {region_.width(), region_.height(), 1};
    auto copyOut = [&](const vk::Image &image, VkBuffer target) {
        vk::imageBarrier(commands, image.handle(), VK_IMAGE_LAYOUT_GENERAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT);
        vkCmdCopyImageToBuffer(commands, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               target, 1, &region);
        vk::imageBarrier(commands, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    };
    copyOut(accum_, colour.handle());
    if (features_.writeAov)
        copyOut(aov_, aov.handle());
    vk::memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

void RayTracer::copyOutUnlessCopied() {
    if (!copiedOut_)
        runner_.run([&](VkCommandBuffer commands) { recordCopyOut(commands); });
    copiedOut_ = false; // the next readback copies again unless a frame did
}

const float *RayTracer::readbackRow(bool aov, uint32_t y) const {
    if (inPlaceReadback_) {
        const vk::Image &image = aov ? aov_ : accum_;
        size_t x0 = region_.x0 - window_.x0 * kTileSize, y0 = region_.y0 - window_.y0 * kTileSize;
        return reinterpret_cast<const float *>(image.mapped() + (y0 + y) * image.rowPitch()) +
               4 * x0;
    }
    const vk::Buffer &copy = aov ? readbackAov_ : readbackColour_;
    return static_cast<const float *>(copy.mapped()) + size_t(y) * region_.width() * 4;
}

TracedImage RayTracer::readback(uint32_t samplesPerPixel) {
    TracedImage out;
    out.width = region_.width();
    out.height = region_.height();
    out.x0 = region_.x0;
    out.y0 = region_.y0;
    out.fullWidth = width_;
    out.fullHeight = height_;
    size_t pixels = size_t(out.width) * out.height;
    copyOutUnlessCopied();
    out.rgba.resize(pixels * 4);
    ReadbackTargets targets;
    if (features_.writeAov) {
        out.depth.resize(pixels);
        out.normal.resize(pixels * 3);
        targets.depth = out.depth.data();
        targets.normal = out.normal.data();
    }
    readRows(samplesPerPixel, targets, out.rgba.data());
    return out;
}

void RayTracer::readbackInto(uint32_t samplesPerPixel, const ReadbackTargets &targets) {
    if ((targets.depth || targets.normal) && !features_.writeAov)
        throw Error("readback: depth and normals need a tracer made with writeAov");
    copyOutUnlessCopied();
    readRows(samplesPerPixel, targets, nullptr);
}

void RayTracer::readRows(uint32_t samplesPerPixel, const ReadbackTargets &targets,
                         float *rgba) const {
    float scale = 1.0f / float(samplesPerPixel);
    uint32_t width = region_.width(), height = region_.height();
    // On one core: in two bands of rows on both (parallelFor), a 320x240 image and its depth
    // took 0.28 ms against 0.17 ms (a loop of views from Python).
    for (uint32_t y = 0; y < height; ++y) {
        size_t first = size_t(y) * width; // the row's first pixel in the targets
        const float *sums = readbackRow(false, y);
        if (rgba)
            for (size_t x = 0; x < width; ++x) {
                for (int c = 0; c < 3; ++c)
                    rgba[(first + x) * 4 + c] = sums[x * 4 + c] * scale;
                rgba[(first + x) * 4 + 3] = 1.0f;
            }
        if (targets.rgb) {
            // Each pixel as one 4-float store whose fourth float the next pixel overwrites
            // (rows are written in order, so the next row's first pixel mends a row's last):
            // a vector multiply and store a pixel instead of three scalar ones (a 320x240 image
            // and its depth read in about 0.18 ms, was 0.25). The image's last pixel stores
            // only three.
            size_t overlapping = y + 1 < height ? width : width - 1;
            for (size_t x = 0; x < overlapping; ++x) {
                float pixel[4];
                for (int c = 0; c < 4; ++c)
                    pixel[c] = sums[x * 4 + c] * scale;
                std::memcpy(targets.rgb + (first + x) * 3, pixel, sizeof pixel);
            }
            for (size_t x = overlapping; x < width; ++x)
                for (int c = 0; c < 3; ++c)
                    targets.rgb[(first + x) * 3 + c] = sums[x * 4 + c] * scale;
        }
        if (!targets.depth && !targets.normal)
            continue;
        const float *aov = readbackRow(true, y);
        if (targets.depth)
            for (size_t x = 0; x < width; ++x)
                targets.depth[first + x] = aov[x * 4 + 3];
        if (targets.normal)
            for (size_t x = 0; x < width; ++x)
                for (int c = 0; c < 3; ++c)
                    targets.normal[(first + x) * 3 + c] = aov[x * 4 + c];
    }
}

} // namespace prism
