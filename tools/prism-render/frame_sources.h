#pragma once
// What traces prism-render's frames: the Vulkan tracer, made once and then given each frame's
// camera, or the CPU reference. A range of frames pays the context, the scene's upload and the
// shader's compilation once (issue 32).
#include <array>
#include <future>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "accel/grid.h"
#include "core/ray_counts.h"
#include "io/image_writer.h"
#include "progress_line.h"
#include "render/ray_tracer.h"
#include "render_options.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace prism {

class DiskCache;

// Where a Vulkan render's wall-clock time goes before the frames (--stats "phases_ms"), so
// start-up can be judged: docs/benchmarks.md has cold and warm figures.
struct VulkanPhases {
    double contextMs = 0.0;     // waiting for the instance, device and queues (made meanwhile)
    double contextMadeMs = 0.0; // making them, on their own thread while the scene loads
    double tracerMs = 0.0;      // scene arrays uploaded, pipeline created for the scene's variant
    double compileMs = 0.0;     // the untimed 8x8 dispatch: lavapipe compiles the shader there
};

// One frame as traced: the image and its timings.
struct FrameOutcome {
    OutputImage image;
    std::vector<double> frameMs;     // timed frames only (after warm-up): GPU timestamps
    std::vector<double> wallMs;      // the same frames by the host's clock (FrameResult)
    RayCounts rays;                  // of one frame
    uint32_t resumeDispatches = 0;   // of the last frame, when traced resumably
    std::array<uint32_t, 3> tiles{}; // of the last frame: FrameResult::tiles
    double framesMs = 0.0;           // every frame on the host's clock, waits included
    double readbackMs = 0.0;         // accumulation (and AOVs) copied back and divided
};

// The Vulkan instance and device, made on a thread of their own while the scene loads and its
// grid builds (they need nothing of the scene): 120-180 ms of lavapipe's start-up (loading
// the driver and LLVM) that no longer adds to the wait (issue 31).
class ContextInBackground {
public:
    ContextInBackground(const RenderOptions &o, const DiskCache *pipelineStore);
    // The context (rethrowing what its creation threw), and how long the caller waited for it.
    vk::Context &get(double &waitedMs, double &madeMs);
    // Returns once the context is made or has failed; from any thread.
    void waitUntilMade() const { ended_.wait(); }

private:
    std::shared_future<void> ended_;
    std::future<std::pair<std::unique_ptr<vk::Context>, double>> made_;
    std::unique_ptr<vk::Context> context_;
};

class FrameSource {
public:
    virtual ~FrameSource() = default;
    // Traces `camera`'s frame (in the scene's centred coordinates) with o.repeat timed frames;
    // `label` heads the progress line and `after` ends it (ProgressLine::update).
    virtual FrameOutcome render(const Camera &camera, const std::string &label,
                                const std::string &after, ProgressLine &progress) = 0;
    virtual std::string device() const = 0;
    // The scene given at construction has had its instances moved and its grid rebuilt
    // (moveToFrame): the next frames must see them.
    virtual void sceneMoved(const Scene &scene, const Grid &grid) = 0;
};

class VulkanFrameSource : public FrameSource {
public:
    // Waits for the context, uploads the scene and compiles the tracer on `firstCamera`'s view.
    // `extent`: the scene's extent found already (PreparedScene::extent), or null.
    VulkanFrameSource(const RenderOptions &o, const Scene &scene, const Grid &grid,
                      const SceneExtent *extent, ContextInBackground &background,
                      const Camera &firstCamera);
    FrameOutcome render(const Camera &camera, const std::string &label, const std::string &after,
                        ProgressLine &progress) override;
    std::string device() const override { return context_->deviceName(); }
    void sceneMoved(const Scene &scene, const Grid &grid) override {
        tracer_->setScene(scene, grid);
    }
    const VulkanPhases &phases() const { return phases_; }
    std::vector<ArrayBytes> sceneArrays() const { return tracer_->sceneArrayBytes(); }
    // Writes the device's pipeline cache back when it changed; bytes written (0: unchanged).
    uint64_t savePipelineCache() { return context_->savePipelineCache(); }
    uint64_t pipelineCacheLoaded() const { return context_->pipelineCacheLoadedBytes(); }

private:
    const RenderOptions &o_;
    VulkanPhases phases_;
    vk::Context *context_ = nullptr;
    std::unique_ptr<RayTracer> tracer_;
};

class CpuFrameSource : public FrameSource {
public:
    CpuFrameSource(const RenderOptions &o, const Scene &scene) : o_(o), scene_(scene) {}
    FrameOutcome render(const Camera &camera, const std::string &label, const std::string &after,
                        ProgressLine &progress) override;
    std::string device() const override { return "CPU reference (double precision)"; }
    void sceneMoved(const Scene &, const Grid &) override {} // it reads the scene each frame

private:
    const RenderOptions &o_;
    const Scene &scene_;
};

} // namespace prism
