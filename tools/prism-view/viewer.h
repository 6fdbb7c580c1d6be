#pragma once
// The viewer's frame loop: window, swapchain and frames in flight around one RayTracer, the
// fly camera, progressive accumulation, the overlay, screenshots and scene reloading. Scripted
// runs (tests, soak) drive it only through a ViewDriver's hooks.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "accel/grid.h"
#include "benchmark.h"
#include "cache/disk_cache.h"
#include "core/timer.h"
#include "fly_camera.h"
#include "frame_stats.h"
#include "overlay.h"
#include "present/present_pass.h"
#include "render/ray_tracer.h"
#include "scene_source.h"
#include "view_driver.h"
#include "view_options.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/frames_in_flight.h"
#include "vk/surface.h"
#include "vk/swapchain.h"
#include "window.h"

namespace prism {

class Viewer final : private ViewControls {
public:
    // Opens the window and loads the scene; throws prism::Error (FileError for the scene)
    // with a message saying what is missing or wrong. `driver` must outlive the viewer.
    Viewer(const ViewOptions &options, ViewDriver &driver);
    ~Viewer();
    Viewer(const Viewer &) = delete;
    Viewer &operator=(const Viewer &) = delete;

    // Runs until the window closes, the script ends or the benchmark is done. Returns the exit
    // status: 1 when validation messages appeared.
    int run();

private:
    // What a submitted frame did, read back when its slot comes round again.
    struct SlotRecord {
        bool submitted = false;
        bool restart = false;  // traced sample 0 of a new accumulation
        bool measured = false; // a benchmark frame
    };

    // Grid and tracer for `scene` with the current toggles; on failure the old ones stay.
    void buildTracer(const Scene &scene);
    // The scene file, through the OBJ cache, timed (loadMs_).
    Scene loadScene();
    bool reloadScene(); // false: the error is shown, the last good scene stays
    void recenterOnCamera();
    // Shows frame frame_ + delta (not before 1) of the scene's animation; the camera jumps to
    // that frame's where the animation moves it, else stays where it was flown.
    void stepFrame(double delta);
    // Centres `loaded` on `point` (in the file's coordinates: scene/scene_origin.h), builds its
    // grid and tracer, and moves the cameras into the new coordinates.
    void showScene(Scene loaded, const glm::dvec3 &point);
    void recreateSwapchain();
    // Traces at 1/scale of the swapchain's size from now on (no-op when unchanged).
    void setTraceScale(uint32_t scale);
    void fitTracerToSwapchain();
    uint32_t motionScale() const;
    void drainFrames();
    void completeSlot(uint32_t slot);
    // Once a frame's pixels overran lavapipe's loop limit: trace resumably from now on (the
    // accumulation starts again), each sample before its frame is recorded.
    void traceResumably();
    void handleKeys(const std::vector<int> &keys);
    FlyInput flyInput(double scroll);
    void updateCamera(uint32_t frame, double seconds, double scroll);
    bool drawFrame(bool measured);
    OverlayStats overlayStats() const;
    bool finished(uint32_t frames) const;
    bool interactiveRun() const; // no script, no benchmark: input drives the camera

    // ViewControls, for the driver.
    void requestWindowSize(uint32_t width, uint32_t height) override;
    bool reloadSceneFrom(const std::filesystem::path &path) override;
    const std::filesystem::path &scenePath() const override { return source_.path(); }
    const Camera &sceneCamera() const override { return scene_.camera; }
    glm::dvec3 sceneOrigin() const override { return scene_.origin; }
    void placeCamera(const Camera &camera) override { fly_.reset(camera); }
    bool setFeatures(const FeatureToggles &features) override; // also the overlay's checkboxes
    const FeatureToggles &features() const override { return toggles_; }
    void saveScreenshot(const std::filesystem::path &base) override; // also F12
    bool converged() const override;
    uint32_t samplesTarget() const override { return options_.samplesPerPixel; }
    uint32_t validationMessages() const override { return context_->validationMessageCount(); }

    ViewOptions options_;
    ViewDriver &driver_;
    GlfwSession glfw_;
    Window window_;
    // Grids, parsed OBJ files and the device's pipeline cache, kept between runs (--cache);
    // before context_, which keeps its pipeline cache here.
    std::unique_ptr<DiskCache> cache_;
    std::unique_ptr<vk::Context> context_;
    vk::Surface surface_;
    std::unique_ptr<vk::Swapchain> swapchain_;
    std::unique_ptr<PresentPass> present_;
    std::unique_ptr<vk::FramesInFlight> frames_;
    std::vector<vk::Buffer> counterSnapshots_; // one per slot, host-visible
    std::vector<SlotRecord> slots_;
    std::unique_ptr<Overlay> overlay_;

    SceneSource source_;
    Scene loaded_;       // as the file has it: each centring starts from here (scene_origin.h)
    Scene scene_;        // centred on where the camera was when last centred, at frame_
    double frame_ = 1.0; // of the scene's animation: its camera and moving instances
    Grid grid_;
    std::string gridKey_; // gridCacheKey of grid_: an unchanged key keeps the grid
    std::string meshKey_; // meshGridsKey of grid_'s prototypes ("" without any)
    // What the last buildTracer did with the grid: kept grid_ (the geometry's key unchanged),
    // built only the level the instances are in over grid_'s mesh grids (the prototypes
    // unchanged: instances moved, the origin moved), or built all of it.
    enum class GridWork { Built, SceneLevel, Kept };
    GridWork gridWork_ = GridWork::Built;
    double gridBuildMs_ = 0.0;
    std::string gridCacheState_ = "off"; // of the last build: "off", "hit" or "miss"
    double loadMs_ = 0.0;                // the scene file's last load
    ObjCacheUse objCache_;               // its OBJ files' cache hits and misses, all loads
    uint32_t recenterings_ = 0;          // the fly camera went far from the origin (scene_origin.h)
    FeatureToggles toggles_;
    std::unique_ptr<RayTracer> tracer_;
    bool resetCounters_ = true;

    FlyCamera fly_;
    Camera tracedCamera_;
    uint32_t samples_ = 0; // in the accumulation image
    uint32_t traceScale_ = 1;
    bool moving_ = false;      // the camera changed within the last kStillMs
    Timer stillTimer_;         // since the camera last changed
    double fullFrameMs_ = 0.0; // a recent full-size accumulation frame, for --motion-scale auto
    bool swapchainDirty_ = false;
    bool overlayVisible_ = true;
    bool dragging_ = false;
    double lastCursorX_ = 0.0, lastCursorY_ = 0.0;

    // Ray counts, from the counter snapshots of completed frames.
    FrameResult lastCounters_;     // cumulative, as of the last completed frame
    FrameResult accumulationBase_; // cumulative when the current accumulation started
    uint64_t benchmarkRays_ = 0;
    double accumulationMs_ = 0.0; // wall clock of the frames that traced it
    FrameStats stats_;
    std::string sceneError_, notice_;
};

} // namespace prism
