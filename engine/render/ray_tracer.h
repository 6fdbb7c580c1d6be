#pragma once
// The ray-tracing pass: owns the scene's GPU buffers, the tracer pipeline for the scene's
// feature set and the accumulation image; records sample dispatches and reads results back.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/ray_counts.h"
#include "render/plane_shadows.h"
#include "render/resume_plan.h"
#include "render/scene_buffers.h"
#include "render/traced_tiles.h"
#include "render/tracer_features.h"
#include "shared/profile_phases.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/timestamp_queries.h"

namespace prism {

// The most samples per pixel any front end accepts (prism-render, prism-view, prism-bench, the
// Python module): the same limit everywhere, well past where an image stops changing.
constexpr uint32_t kMaxSamplesPerPixel = 65536;

struct FrameResult {
    double gpuMs = 0.0; // from GPU timestamps, all sample dispatches of the frame
    // From the host's clock: recording the frame's commands (the tile lists and their start
    // distances included) to their fences. What a caller waits for a frame; on lavapipe the
    // timestamps leave out the queue's own start and end of each submission.
    double wallMs = 0.0;
    RayCounts rays;
    // Pixels lavapipe's loop limit cut short (loop_limit.glsl). renderFrame never returns
    // such a frame: it traces it again resumably (resumeDispatches > 0).
    uint64_t loopCutPixels = 0;
    uint32_t resumeDispatches = 0; // dispatches of resumable tracing (shaders/resume.glsl)
    // With TracerOptions::profile: nanoseconds per phase (shared/profile_phases.h), summed over
    // the frame's subgroups; zero otherwise.
    std::array<uint64_t, gpu::kProfileSlots> phaseNs{};
    // The image's tiles by the tracer that ran them (render/traced_tiles.h, tileClasses): the
    // full tracer, the one for planes only, the background's. Resumable frames: all full.
    std::array<uint32_t, 3> tiles{};
};

// Where RayTracer::readbackInto writes, each of the region's size (row 0 = top); null: not
// wanted. depth and normal need TracerOptions::writeAov.
struct ReadbackTargets {
    float *rgb = nullptr;    // 3 floats a pixel: mean radiance (TracedImage::rgba less alpha)
    float *depth = nullptr;  // 1 a pixel (TracedImage::depth)
    float *normal = nullptr; // 3 a pixel (TracedImage::normal)
};

struct TracedImage {
    uint32_t width = 0, height = 0; // the region's (TracerOptions::region), else the image's
    uint32_t x0 = 0, y0 = 0;        // where the region starts in the image
    uint32_t fullWidth = 0, fullHeight = 0; // the whole image the camera sees
    std::vector<float> rgba;                // mean radiance, alpha 1, row 0 = top
    std::vector<float> depth;  // with writeAov: distance to the hit of the centre ray, +inf miss
    std::vector<float> normal; // with writeAov: xyz per pixel, facing the ray, 0 on a miss
};

class RayTracer {
public:
    // `scene` centred on the camera (scene/scene_origin.h) and `grid` built from it; cameras
    // given later are in the same coordinates.
    RayTracer(vk::Context &context, const Scene &scene, const Grid &grid, uint32_t width,
              uint32_t height, const TracerOptions &options);
    ~RayTracer();

    // Records dispatches for samples [firstSample, firstSample + count) of `samplesPerPixel`.
    // Sample 0 overwrites the accumulation, later samples add to it.
    void recordSamples(VkCommandBuffer commands, const Camera &camera, uint32_t firstSample,
                       uint32_t count, uint32_t samplesPerPixel);

    // Traces one 8x8 tile, untimed and thrown away (the next frame's first sample overwrites
    // it), so that a device that compiles the shader at its first dispatch (lavapipe) does so
    // here and not inside a timed frame: a single render then needs no warm-up frame.
    void compile(const Camera &camera);

    // A whole frame: all samples, submitted and waited for, with GPU time and ray counts.
    // With `progress`, samples go in several submissions and progress gets the fraction done.
    // A frame whose pixels overran lavapipe's loop limit is traced again resumably, and from
    // then on every frame of this tracer is. Throws prism::Error when a sample cannot be
    // finished even so (more walks than a pixel's log holds).
    // With `copyOut`, the frame's last submission also copies the image out for readback, which
    // then submits nothing (on lavapipe a submission and its wait cost about 0.7 ms). An image
    // read in place (readsInPlace) needs no copy: readback after any frame submits nothing.
    FrameResult renderFrame(const Camera &camera, uint32_t samplesPerPixel,
                            const std::function<void(double)> &progress = {}, bool copyOut = false);

    // Every ray the frame in progress has counted so far (primary, shadow, secondary): read by
    // renderFrame's progress callback, which runs after each submission's fence, so that a
    // long render can show its rays per second before the frame is done.
    uint64_t raysCounted() const { return decodeCounters(stats_.mapped()).rays.total(); }

    // The accumulation (and AOVs) of the region (TracerOptions::region; else the whole image)
    // on the host, divided by the sample count: read where the tracer wrote it (readsInPlace),
    // else from a copy.
    TracedImage readback(uint32_t samplesPerPixel);
    // The same into the caller's arrays, in one pass over the image (the Python
    // module's NumPy arrays: a TracedImage copied again took a 320x240 view 0.5 ms).
    void readbackInto(uint32_t samplesPerPixel, const ReadbackTargets &targets);
    // Whether the host reads the images where the tracer wrote them (a CPU device whose linear
    // images can be storage images), not through a copy (TracerOptions::copiedReadback).
    bool readsInPlace() const { return inPlaceReadback_; }
    // The class of each 8x8 tile (row by row) in the last frame traced (tileClasses): which
    // tracer ran it. Empty before the first frame and after resumable ones (all full there).
    const std::vector<uint8_t> &lastTileClasses() const { return lastTileClasses_; }
    // How many times this tracer has made tile lists: once a frame, and once for all the
    // progressive samples of a resting camera (recordSamples).
    uint64_t tileListsMade() const { return keptTiles_.made; }
    // The sampling seed of the frames traced from now on (shared/sampling.h: samplingKey): 0,
    // the default, draws the samples every earlier image drew; another seed draws another
    // independent set. Pixels draw by their place in the whole image, so a region or tile
    // traced under a seed is that seed's whole image's. Throws prism::Error above kMaxSeed.
    void setSeed(uint32_t seed);
    uint32_t seed() const { return seed_; }

    // Resumable tracing (shaders/resume.glsl) for callers that record their own frames (the
    // viewer), once their counters show cut pixels: enableResumable switches this tracer for
    // good (waits for the device); traceSampleNow traces one sample of the accumulation now,
    // in as many submissions as it takes, and waits. Its counters add to the recorded ones
    // (or start again, with resetCounters).
    // Throws prism::Error as renderFrame does.
    bool resumable() const { return features_.resumable; }
    void enableResumable();
    FrameResult traceSampleNow(const Camera &camera, uint32_t sample, uint32_t samplesPerPixel,
                               bool resetCounters);

    // For callers that record their own frames (the viewer). The ray and over-budget counters
    // add up over every dispatch until reset. A snapshot copies them, after the dispatches
    // recorded before it, into `target` (host-visible, counterBytes() long) for decodeCounters.
    void recordResetCounters(VkCommandBuffer commands);
    void recordCounterSnapshot(VkCommandBuffer commands, VkBuffer target) const;
    static VkDeviceSize counterBytes();
    static FrameResult decodeCounters(const void *snapshot); // gpuMs stays 0
    // New accumulation (and AOV) images of another size, for the whole image (a region is
    // dropped); waits for the device to be idle. Afterwards the accumulation is undefined until
    // sample 0 is traced again.
    void resize(uint32_t width, uint32_t height);

    // The same scene with its instances moved (session/prepared_scene.h: moveToFrame) and `grid`
    // built for it: the arrays uploaded again, the compiled variants kept where the scene's
    // features are unchanged (recompiled where they are not); waits for the device to be idle.
    // Frames traced from then on see the new scene; the accumulation is left as it is.
    void setScene(const Scene &scene, const Grid &grid);

    const vk::Image &accumulation() const { return accum_; }
    const TracerFeatures &features() const { return features_; }
    // The scene's arrays on the device, as uploaded (--stats: what instancing saves shows here).
    std::vector<ArrayBytes> sceneArrayBytes() const { return arrayBytes(scene_); }
    // Whether the full tiles' pipeline was made from its module with the specialization folded
    // in (TracerOptions::foldSpecialization).
    bool specializationFolded() const { return pipeline_->folded(); }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    const PixelRect &region() const { return region_; }

private:
    // One dispatch of groupsX x groupsY 8x8 tiles with `params`, then the barrier that lets the
    // next dispatch read the accumulation it wrote.
    void recordDispatch(VkCommandBuffer commands, const gpu::GpuFrameParams &params,
                        uint32_t groupsX, uint32_t groupsY);
    // recordSamples with the frame's parameters and tile lists already made.
    void recordSamples(VkCommandBuffer commands, gpu::GpuFrameParams params, const TileLists &lists,
                       uint32_t firstSample, uint32_t count);
    // The class of each tile for `params`' camera (render/traced_tiles.h, tileClasses); all
    // full when culling is off. `starts`: the frame's tile start distances, where made (the
    // tiles that see the geometry are read from them).
    std::vector<uint8_t> frameTileClasses(const gpu::GpuFrameParams &params,
                                          const std::vector<float> *starts) const;
    // The frame's tile lists by class, the classes kept for lastTileClasses; with `reuse`, the
    // last lists where they were made for the same parameters. Valid until the next call or
    // resize().
    const TileLists &frameTiles(const gpu::GpuFrameParams &params, bool reuse);
    // Writes `lists` into the tile list inside the command buffer (so that frames in flight
    // each read their own), ordered after earlier dispatches' reads and before later ones.
    void recordTileList(VkCommandBuffer commands, const TileLists &lists);
    // One sample over the whole image: the full tracer on the list's first `full` tiles, the
    // tracer of planes only up to `traced`, the background variant on the rest.
    void recordSample(VkCommandBuffer commands, const gpu::GpuFrameParams &params,
                      const TileLists &lists);
    // makeFrameParams with the scene's plane and light counts (the shader's loop bounds).
    gpu::GpuFrameParams frameParams(const Camera &camera, uint32_t samplesPerPixel) const;
    void recordAccumulationBarrier(VkCommandBuffer commands);
    // One dispatch of `pipeline` over entries [first, first + count) of the tile list.
    void recordTiles(VkCommandBuffer commands, const vk::ComputePipeline &pipeline,
                     gpu::GpuFrameParams params, uint32_t first, uint32_t count);
    // The images and the tile list, sized to the region's tiles (window_), and their bindings.
    void createImages(uint32_t width, uint32_t height);
    void bindImages(vk::ComputePipeline &pipeline);
    // Whether tiles that see only planes may get the tracer without a grid: the scene has
    // planes and grid geometry, and a plane hit starts no secondary ray that could reach the
    // grid except through one mirror plane, whose reflections the tiles are classed by.
    enum class PlaneTiles {
        Never,           // every plane tile keeps the grid
        NoSecondaryRays, // depth 1, or no plane reflects or refracts
        OneMirror,       // one plane reflects, the others are matte: mirror images too
    };
    // `mirror`: the reflecting plane's index, for OneMirror.
    PlaneTiles planeTilesMode(const Scene &scene, size_t &mirror) const;
    vk::ComputePipeline &planesPipeline();
    // The pipeline for features_, with every binding written.
    void createPipeline();
    // Which SPIR-V: trace.comp as it is, or compiled with PRISM_PLANES_ONLY or
    // PRISM_BACKGROUND_ONLY (render/traced_tiles.h); the profiling build uses the full one.
    enum class Module { Full, PlanesOnly, BackgroundOnly };
    std::unique_ptr<vk::ComputePipeline> createTracerPipeline(const TracerFeatures &features,
                                                              Module module);
    // createTracerPipeline's two halves: the pipeline alone (it reads no member but the
    // context, so it may run on another thread), and its bindings.
    std::unique_ptr<vk::ComputePipeline> compileTracerPipeline(const TracerFeatures &features,
                                                               Module module) const;
    void bindTracerPipeline(vk::ComputePipeline &pipeline);
    // pipeline_ compiled while writeArrays() runs (the constructor, for big scenes).
    void compileBeside(const std::function<void()> &writeArrays);
    // Resumable tracing: each sample of each tile dispatched until all its pixels are done.
    void startResuming();
    FrameResult renderResumable(const Camera &camera, uint32_t samplesPerPixel,
                                const std::function<void(double)> &progress);
    void traceSampleResumably(const Camera &camera, uint32_t sample, uint32_t samplesPerPixel,
                              bool resetCounters, FrameResult &result);

    // planeGuards_ for the scene as it is now (planeTilesMode, TracerOptions::cullPlaneTiles).
    void choosePlaneGuards(const Scene &scene);

    vk::Context &context_;
    TracerOptions options_;           // as given: setScene chooses the variants again by them
    uint32_t width_ = 0, height_ = 0; // the whole image's
    PixelRect region_;                // what readback returns: the whole image, or a part
    // The tiles round region_: what the frames trace and the accumulation holds, from the
    // store origin (window_.x0, window_.y0) * kTileSize on (frameStoreOrigin).
    TileRect window_;
    uint32_t storeWidth_ = 0, storeHeight_ = 0; // the accumulation's size
    TracerFeatures features_;
    ArrayLimits limits_;
    vk::CommandRunner runner_;
    SceneBuffers scene_;
    vk::Buffer stats_;
    uint32_t planeCount_ = 0, lightCount_ = 0;
    uint32_t seed_ = 0;
    uint64_t resumeMemoryBytes_ = 0;
    ResumePlan resumePlan_;
    vk::Buffer resumeRecords_; // resumable tracing; 32-byte stand-ins otherwise
    vk::Buffer walkLog_;
    vk::Image accum_;
    vk::Image aov_;
    // Host-visible copies of accum_ and aov_ for readback, kept between frames: made anew for
    // each, their allocation and first touch cost a 320x240 frame 0.5 ms (a loop of views).
    // Unused where inPlaceReadback_: the images are host-readable and read where they are.
    vk::Buffer readbackColour_, readbackAov_;
    bool inPlaceReadback_ = false;
    // The readback buffers hold the accumulation as it is now (renderFrame's copyOut): every
    // recording that writes the accumulation clears it.
    bool copiedOut_ = false;
    void recordCopyOut(VkCommandBuffer commands);
    void copyOutUnlessCopied(); // readback's copy, where the frame did not make it
    // Row y of the region as read back (the image itself, or its copy): RGBA floats.
    const float *readbackRow(bool aov, uint32_t y) const;
    // The region's rows into `targets` (and into `rgba`, 4 floats a pixel with alpha 1, where
    // not null), divided by the sample count.
    void readRows(uint32_t samplesPerPixel, const ReadbackTargets &targets, float *rgba) const;
    vk::Buffer tileList_; // rg32ui, one entry per tile of the image: tile, start distance
    vk::BufferView tileListView_;
    vk::TimestampQueries timestamps_;
    std::unique_ptr<vk::ComputePipeline> pipeline_;
    // The tracer compiled without geometry, for tiles that see only the background; null when
    // TracerOptions::cullMissTiles is off.
    std::unique_ptr<vk::ComputePipeline> missPipeline_;
    // The tracer without the grid, for tiles that see only planes out of the grid's shadows
    // (tileClasses), where planeGuards_: made by planesPipeline() when a view first has some.
    std::unique_ptr<vk::ComputePipeline> planesPipeline_;
    SceneExtent extent_;
    // What tiles are classed with planes only by (render/plane_shadows.h), where they are:
    // TracerOptions::cullPlaneTiles, planeTilesMode, and shadows with a bound.
    std::optional<PlaneTileGuards> planeGuards_;
    std::vector<uint8_t> lastTileClasses_; // FrameResult::tiles of the last recordSamples
    // The last tile lists made and the frame parameters they were made for: they follow from
    // those alone, and the viewer asks again at every progressive sample of a resting camera.
    struct KeptTiles {
        std::optional<gpu::GpuFrameParams> params;
        std::vector<uint8_t> classes;
        TileLists lists;
        uint64_t made = 0;
    };
    KeptTiles keptTiles_;
    bool tileStarts_ = false;     // TracerOptions::tileStarts, where the tiles are culled
    uint32_t dispatchShares_ = 0; // lavapipe: the threads a dispatch is split among; else 0
};

} // namespace prism
