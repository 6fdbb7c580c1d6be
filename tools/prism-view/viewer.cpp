#include "viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <GLFW/glfw3.h>

#include "accel/grid_cache.h"
#include "core/error.h"
#include "core/timer.h"
#include "render_metadata.h"
#include "scene/camera_animation.h"
#include "scene/number_parser.h"
#include "scene/placement_animation.h"
#include "scene/scene_origin.h"
#include "screenshot.h"
#include "vk/vk_check.h"

namespace prism {
namespace {

constexpr uint32_t kFramesInFlight = 2;
constexpr uint32_t kBenchmarkWarmupFrames = 5;
// A camera still for this long is "still": back to full size, accumulating. The pause keeps a
// slow drag from switching sizes every frame.
constexpr double kStillMs = 150.0;
// --motion-scale auto aims a moving frame at this (about 20 FPS).
constexpr double kMotionFrameMs = 50.0;

std::unique_ptr<DiskCache> openCache(const ViewOptions &options) {
    if (options.cacheDir.empty())
        return nullptr;
    return std::make_unique<DiskCache>(DiskCacheOptions{options.cacheDir});
}

std::unique_ptr<vk::Context> makeContext(const ViewOptions &options, const DiskCache *cache) {
    vk::ContextOptions contextOptions;
    contextOptions.pipelineStore = cache;
    contextOptions.validation = options.validation;
    contextOptions.deviceNameFilter = options.deviceFilter;
    contextOptions.instanceExtensions = GlfwSession::requiredInstanceExtensions();
    contextOptions.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
    return std::make_unique<vk::Context>(contextOptions);
}

std::string windowTitle(const std::filesystem::path &scene) {
    return "prism-view - " + scene.filename().string();
}

FrameResult minus(const FrameResult &a, const FrameResult &b) {
    FrameResult d;
    d.rays.primary = a.rays.primary - b.rays.primary;
    d.rays.shadow = a.rays.shadow - b.rays.shadow;
    d.rays.secondary = a.rays.secondary - b.rays.secondary;
    d.loopCutPixels = a.loopCutPixels - b.loopCutPixels;
    return d;
}

// `centred` at `frame` of its animation: its camera the frame's, its keyed instances moved. The
// camera line's own camera is then gone from this copy: the next frame starts from the loaded
// scene again (showScene).
void setFrame(Scene &centred, double frame) {
    Camera camera = cameraAt(centred, frame);
    if (placementsAnimated(centred))
        centred.instances = instancesAt(centred, frame);
    centred.camera = camera;
}

} // namespace

Viewer::Viewer(const ViewOptions &options, ViewDriver &driver)
    : options_(options), driver_(driver),
      window_(options.width, options.height, windowTitle(options.scenePath)),
      cache_(openCache(options)), context_(makeContext(options, cache_.get())),
      source_(options.scenePath), frame_(options.frame), fly_(Camera{}, 1.0f) {
    surface_ = window_.createSurface(context_->instance());
    VkExtent2D size = window_.framebufferSize();
    vk::SwapchainOptions swapchainOptions{size, options_.vsync, VK_NULL_HANDLE};
    swapchain_ = std::make_unique<vk::Swapchain>(*context_, surface_.handle(), swapchainOptions);
    present_ = std::make_unique<PresentPass>(*context_, *swapchain_);
    frames_ = std::make_unique<vk::FramesInFlight>(*context_, kFramesInFlight);
    for (uint32_t i = 0; i < kFramesInFlight; ++i)
        counterSnapshots_.emplace_back(*context_, RayTracer::counterBytes(),
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    slots_.resize(kFramesInFlight);
    overlay_ =
        std::make_unique<Overlay>(window_, *context_, present_->renderPass(), kFramesInFlight);

    toggles_.grid = options_.grid.mode != GridOptions::Mode::Off;
    objCache_.cache = cache_.get();
    Scene scene = loadScene(); // at start a broken scene is fatal: there is nothing to show
    for (const std::string &warning : scene.warnings)
        std::fprintf(stderr, "%s\n", warning.c_str());
    glm::dvec3 eye = scene.camera.eye;
    showScene(std::move(scene), eye);
    fly_ = FlyCamera(scene_.camera, flySpeedFor(scene_, grid_.boundsMin, grid_.boundsMax));
    tracedCamera_ = scene_.camera;
}

Viewer::~Viewer() {
    if (context_) {
        vkDeviceWaitIdle(context_->device());
        try { // the pipelines this run made, for the next one (a GPU driver's compile)
            context_->savePipelineCache();
        } catch (const Error &e) {
            std::fprintf(stderr, "prism-view: %s\n", e.what());
        }
    }
}

Scene Viewer::loadScene() {
    Timer timer;
    Scene scene = source_.load(&objCache_);
    loadMs_ = timer.elapsedMs();
    return scene;
}

void Viewer::buildTracer(const Scene &scene) {
    GridOptions gridOptions = options_.grid;
    if (!toggles_.grid)
        gridOptions.mode = GridOptions::Mode::Off;
    else if (gridOptions.mode == GridOptions::Mode::Off)
        gridOptions.mode = GridOptions::Mode::Auto; // --grid off, then switched on
    // A reload that changed no geometry (a material, a light, a texture) or a toggle other than
    // the grid's keeps the grid: its key is what the build reads (accel/grid_cache.h). One that
    // left the prototypes as they were (instances moved, or the origin: prototypes keep their
    // own space) builds only the instances' level over the mesh grids it has.
    // The prototypes' digest is part of the grid's key: read once for both.
    std::string meshKey = meshGridsKey(scene);
    std::string gridKey = gridCacheKey(scene, gridOptions, meshKey);
    bool same = tracer_ && gridKey == gridKey_;
    GridWork work = !tracer_                                  ? GridWork::Built
                    : same                                    ? GridWork::Kept
                    : !meshKey.empty() && meshKey == meshKey_ ? GridWork::SceneLevel
                                                              : GridWork::Built;
    std::optional<Grid> built;
    double buildMs = gridBuildMs_;
    std::string cacheState = gridCacheState_;
    if (work != GridWork::Kept) {
        Timer buildTimer;
        // A whole grid comes from the disk cache where it was built before, in this run or
        // another (prism-render's too, for the same options and camera).
        GridCacheOutcome outcome;
        bool cached = cache_ && gridOptions.mode != GridOptions::Mode::Off;
        built = work == GridWork::SceneLevel
                    ? buildGridOverMeshGrids(scene, gridOptions, grid_.meshGrids)
                    : buildGridCached(scene, gridOptions,
                                      GridCachePolicy{cached ? cache_.get() : nullptr, gridKey},
                                      &outcome);
        buildMs = buildTimer.elapsedMs();
        cacheState = work == GridWork::SceneLevel ? "off" : outcome.state;
    }
    const Grid &grid = work == GridWork::Kept ? grid_ : *built;
    TracerOptions tracerOptions;
    tracerOptions.maxDepth = options_.maxDepth;
    tracerOptions.shadows = toggles_.shadows;
    tracerOptions.reflection = toggles_.reflection;
    tracerOptions.transmission = toggles_.refraction;
    VkExtent2D extent = swapchain_->extent();
    uint32_t width = std::max(1u, extent.width / traceScale_);
    uint32_t height = std::max(1u, extent.height / traceScale_);
    // Built before the old one goes, so a failure leaves the last good scene on screen.
    auto tracer = std::make_unique<RayTracer>(*context_, scene, grid, width, height, tracerOptions);
    drainFrames();
    tracer_ = std::move(tracer);
    if (built)
        grid_ = std::move(*built);
    gridKey_ = std::move(gridKey);
    meshKey_ = std::move(meshKey);
    gridWork_ = work;
    gridBuildMs_ = buildMs;
    gridCacheState_ = std::move(cacheState);
    present_->setSource(tracer_->accumulation());
    resetCounters_ = true;
    lastCounters_ = {};
    accumulationBase_ = {};
    samples_ = 0;
}

bool Viewer::reloadScene() {
    try {
        // Centred where the flown camera is, which stays where it was (in the file's terms).
        showScene(loadScene(), scene_.origin + fly_.camera().eye);
        sceneError_.clear();
        notice_ = "reloaded " + source_.path().filename().string() +
                  (gridWork_ == GridWork::Kept         ? " (same geometry: grid kept)"
                   : gridWork_ == GridWork::SceneLevel ? " (same meshes: their grids kept)"
                                                       : "");
        std::fprintf(stderr, "prism-view: %s\n", notice_.c_str());
        return true;
    } catch (const Error &e) {
        sceneError_ = e.what();
        std::fprintf(stderr, "%s\n", e.what());
        return false;
    }
}

bool Viewer::setFeatures(const FeatureToggles &features) {
    if (features == toggles_)
        return true;
    FeatureToggles previous = toggles_;
    toggles_ = features;
    try {
        buildTracer(scene_);
        return true;
    } catch (const Error &e) {
        toggles_ = previous;
        notice_ = e.what();
        std::fprintf(stderr, "prism-view: %s\n", notice_.c_str());
        return false;
    }
}

void Viewer::showScene(Scene loaded, const glm::dvec3 &point) {
    Scene centred = loaded;
    centerOn(centred, point);
    setFrame(centred, frame_);
    buildTracer(centred); // throws before anything changed
    glm::dvec3 shift = centred.origin - scene_.origin;
    loaded_ = std::move(loaded);
    scene_ = std::move(centred);
    // The cameras keep their place in the file's coordinates, so a still camera stays still.
    tracedCamera_.eye -= shift;
    tracedCamera_.look -= shift;
    Camera flown = fly_.camera();
    flown.eye -= shift;
    flown.look -= shift;
    fly_.reset(flown);
}

// Floats are finest at the origin, which sits at the camera. A flight of many view distances
// would coarsen them where the camera now looks, so the origin moves to the camera: the grid is
// rebuilt and the buffers uploaded, a reload without reading files (e.g. 11 ms for `scene`,
// 52 ms for `bunny`, 138 ms for `showcase` on lavapipe's 2-core host: their `build_ms`). It
// happens once per ~80 view distances flown (needsRecentering).
void Viewer::recenterOnCamera() {
    showScene(loaded_, scene_.origin + fly_.camera().eye);
    ++recenterings_;
    std::fprintf(stderr, "prism-view: origin moved to the camera (%u), grid rebuilt in %.1f ms\n",
                 recenterings_, gridBuildMs_);
}

void Viewer::stepFrame(double delta) {
    if (!sceneAnimated(loaded_)) {
        notice_ = "the scene has no animation (docs/scene-format.md, \"Animation\")";
        return;
    }
    double previous = frame_;
    frame_ = std::max(1.0, frame_ + delta);
    try {
        showScene(loaded_, scene_.origin + fly_.camera().eye);
    } catch (const Error &e) {
        frame_ = previous;
        notice_ = e.what();
        std::fprintf(stderr, "prism-view: %s\n", notice_.c_str());
        return;
    }
    if (loaded_.cameraAnimation.animated())
        fly_.reset(scene_.camera);
    notice_ = "frame " + formatNumber(frame_);
}

void Viewer::drainFrames() {
    vkDeviceWaitIdle(context_->device());
    // Slots complete in submission order; the current one is the oldest.
    for (uint32_t i = 0; i < kFramesInFlight; ++i)
        completeSlot((frames_->current() + i) % kFramesInFlight);
}

void Viewer::completeSlot(uint32_t slot) {
    SlotRecord &record = slots_[slot];
    if (!record.submitted)
        return;
    FrameResult counters = RayTracer::decodeCounters(counterSnapshots_[slot].mapped());
    if (record.restart)
        accumulationBase_ = lastCounters_;
    uint64_t rays = counters.rays.total() - lastCounters_.rays.total();
    stats_.addRays(rays);
    if (record.measured)
        benchmarkRays_ += rays;
    lastCounters_ = counters;
    record = SlotRecord{};
}

void Viewer::recreateSwapchain() {
    VkExtent2D size = window_.framebufferSize();
    if (size.width == 0 || size.height == 0)
        return; // minimised: wait until there is something to draw into
    drainFrames();
    vk::SwapchainOptions swapchainOptions{size, options_.vsync, swapchain_->handle()};
    auto replacement =
        std::make_unique<vk::Swapchain>(*context_, surface_.handle(), swapchainOptions);
    swapchain_ = std::move(replacement); // the old one is retired, then destroyed
    if (present_->resetSwapchain(*swapchain_))
        overlay_->setRenderPass(present_->renderPass());
    fitTracerToSwapchain();
    present_->setSource(tracer_->accumulation());
    swapchainDirty_ = false;
    driver_.swapchainRebuilt(swapchain_->extent().width, swapchain_->extent().height);
}

void Viewer::fitTracerToSwapchain() {
    VkExtent2D extent = swapchain_->extent();
    uint32_t width = std::max(1u, extent.width / traceScale_);
    uint32_t height = std::max(1u, extent.height / traceScale_);
    if (width == tracer_->width() && height == tracer_->height())
        return;
    tracer_->resize(width, height); // waits for the device: no frame still reads the old image
    present_->setSource(tracer_->accumulation());
    samples_ = 0;
}

void Viewer::setTraceScale(uint32_t scale) {
    if (scale == traceScale_)
        return;
    traceScale_ = scale;
    fitTracerToSwapchain();
}

uint32_t Viewer::motionScale() const {
    if (options_.motionScale > 0)
        return options_.motionScale;
    if (fullFrameMs_ <= kMotionFrameMs)
        return 1;
    // Cost goes with the pixel count: scale s divides it by s^2.
    double scale = std::ceil(std::sqrt(fullFrameMs_ / kMotionFrameMs));
    return uint32_t(std::min(scale, 8.0));
}

void Viewer::handleKeys(const std::vector<int> &keys) {
    bool typing = overlay_->wantsKeyboard();
    for (int key : keys) {
        if (typing && key != GLFW_KEY_F5 && key != GLFW_KEY_F12)
            continue;
        switch (key) {
        case GLFW_KEY_H:
            overlayVisible_ = !overlayVisible_;
            break;
        case GLFW_KEY_R:
            fly_.reset(scene_.camera);
            break;
        case GLFW_KEY_F5:
            reloadScene();
            break;
        case GLFW_KEY_LEFT_BRACKET:
            stepFrame(-1.0);
            break;
        case GLFW_KEY_RIGHT_BRACKET:
            stepFrame(1.0);
            break;
        case GLFW_KEY_F12:
            saveScreenshot(defaultScreenshotBase(options_.scenePath));
            break;
        case GLFW_KEY_ESCAPE:
            glfwSetWindowShouldClose(window_.handle(), GLFW_TRUE);
            break;
        default:
            break;
        }
    }
}

FlyInput Viewer::flyInput(double scroll) {
    FlyInput input;
    if (!overlay_->wantsKeyboard()) {
        auto axis = [&](int plus, int minus) {
            return float(window_.keyDown(plus)) - float(window_.keyDown(minus));
        };
        input.move = {axis(GLFW_KEY_D, GLFW_KEY_A), axis(GLFW_KEY_E, GLFW_KEY_Q),
                      axis(GLFW_KEY_W, GLFW_KEY_S)};
        input.fast = window_.keyDown(GLFW_KEY_LEFT_SHIFT) || window_.keyDown(GLFW_KEY_RIGHT_SHIFT);
    }
    double x = 0.0, y = 0.0;
    window_.cursor(x, y);
    bool down = window_.mouseDown(GLFW_MOUSE_BUTTON_LEFT);
    if (down && !dragging_ && !overlay_->wantsMouse())
        dragging_ = true; // a drag that starts on the overlay belongs to the overlay
    else if (!down)
        dragging_ = false;
    if (dragging_)
        input.turnPixels = {float(x - lastCursorX_), float(y - lastCursorY_)};
    lastCursorX_ = x;
    lastCursorY_ = y;
    if (!overlay_->wantsMouse())
        input.zoomSteps = float(scroll);
    return input;
}

void Viewer::updateCamera(uint32_t frame, double seconds, double scroll) {
    if (options_.benchmarkFrames > 0) {
        uint32_t measured = frame < kBenchmarkWarmupFrames ? 0 : frame - kBenchmarkWarmupFrames;
        fly_.reset(benchmarkCamera(scene_.camera, measured, options_.benchmarkFrames));
    } else if (interactiveRun()) {
        // A slow frame (a shader compile, a reload) must not turn into a long jump.
        fly_.update(flyInput(scroll), std::min(seconds, 0.25));
    } // else scripted: the driver's input hook placed the camera, or left it where it was
    const Camera &flown = fly_.camera();
    if (needsRecentering(flown.eye, glm::length(flown.look - flown.eye)))
        recenterOnCamera();
    if (!sameCamera(fly_.camera(), tracedCamera_)) {
        tracedCamera_ = fly_.camera();
        samples_ = 0; // any change restarts the accumulation
        stillTimer_.reset();
        if (!moving_ && interactiveRun())
            setTraceScale(motionScale()); // chosen once per motion, so sizes do not flicker
        moving_ = true;
    } else if (moving_ && stillTimer_.elapsedMs() >= kStillMs) {
        moving_ = false;
        setTraceScale(1);
    }
}

void Viewer::traceResumably() {
    drainFrames();
    notice_ = std::to_string(minus(lastCounters_, accumulationBase_).loopCutPixels) +
              " pixels overran the loop limit: tracing resumably from now on";
    std::fprintf(stderr, "prism-view: %s\n", notice_.c_str());
    tracer_->enableResumable();
    resetCounters_ = true;
    lastCounters_ = {};
    accumulationBase_ = {};
    samples_ = 0;
}

bool Viewer::drawFrame(bool measured) {
    frames_->waitCurrent();
    uint32_t slot = frames_->current();
    completeSlot(slot);
    if (!tracer_->resumable() && lastCounters_.loopCutPixels > 0)
        traceResumably();
    // A resumable sample is traced now, in submissions of its own, before this frame's
    // commands: no frame in flight may read the accumulation meanwhile.
    bool tracedNow = false;
    if (tracer_->resumable() && samples_ < options_.samplesPerPixel) {
        drainFrames();
        try {
            tracer_->traceSampleNow(tracedCamera_, samples_, options_.samplesPerPixel,
                                    resetCounters_);
            resetCounters_ = false;
            tracedNow = true;
        } catch (const Error &e) {
            notice_ = e.what();
            std::fprintf(stderr, "prism-view: %s\n", notice_.c_str());
            samples_ = options_.samplesPerPixel; // nothing more to trace for this view
        }
    }

    uint32_t imageIndex = 0;
    VkResult acquired =
        vkAcquireNextImageKHR(context_->device(), swapchain_->handle(), UINT64_MAX,
                              frames_->imageAcquired(), VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        swapchainDirty_ = true;
        return false;
    }
    if (acquired != VK_SUBOPTIMAL_KHR)
        VK_CHECK(acquired);

    VkCommandBuffer commands = frames_->begin();
    SlotRecord &record = slots_[slot];
    record.submitted = true;
    record.measured = measured;
    if (resetCounters_) {
        tracer_->recordResetCounters(commands);
        resetCounters_ = false;
    }
    bool traced = tracedNow || samples_ < options_.samplesPerPixel;
    if (traced) {
        record.restart = samples_ == 0;
        // Sample s of N: the same stratum and random numbers prism-render --spp N uses.
        if (!tracedNow)
            tracer_->recordSamples(commands, tracedCamera_, samples_, 1, options_.samplesPerPixel);
        samples_ += 1;
    }
    tracer_->recordCounterSnapshot(commands, counterSnapshots_[slot].handle());
    present_->record(commands, imageIndex, [&](VkCommandBuffer c) { overlay_->record(c); });
    VkSemaphore renderDone = swapchain_->renderDone(imageIndex);
    frames_->submit(renderDone);

    VkSwapchainKHR swapchain = swapchain_->handle();
    VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    presentInfo.waitSemaphoreCount = 1;
    presentInfo.pWaitSemaphores = &renderDone;
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &swapchain;
    presentInfo.pImageIndices = &imageIndex;
    VkResult presented = vkQueuePresentKHR(context_->queue(), &presentInfo);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
        acquired == VK_SUBOPTIMAL_KHR)
        swapchainDirty_ = true;
    else
        VK_CHECK(presented);
    return traced;
}

void Viewer::saveScreenshot(const std::filesystem::path &base) {
    drainFrames();
    if (samples_ == 0) {
        notice_ = "nothing traced yet; no screenshot";
        return;
    }
    FrameResult accumulation = minus(lastCounters_, accumulationBase_);
    if (accumulation.loopCutPixels > 0) {
        notice_ = std::to_string(accumulation.loopCutPixels) +
                  " pixels cut by the loop limit; screenshot not saved";
        std::fprintf(stderr, "prism-view: %s\n", notice_.c_str());
        return;
    }
    RenderRecord record;
    record.commandLine = options_.commandLine;
    record.scenePath = options_.scenePath.string();
    record.device = context_->deviceName();
    record.backend = "vulkan";
    record.gridResolution = gridText(grid_);
    record.rays = accumulation.rays;
    record.renderTimeMs = accumulationMs_;
    record.renderTimeMedianMs = accumulationMs_;
    record.gridBuildMs = gridBuildMs_;
    record.gridChoice = grid_.choice;
    record.gridCells = grid_.cellCount();
    record.gridBytes = grid_.bytes();
    record.mraysPerSecond =
        accumulationMs_ > 0.0 ? double(accumulation.rays.total()) / (accumulationMs_ * 1e3) : 0.0;
    record.samplesPerPixel = samples_;
    record.maxDepth = options_.maxDepth;
    try {
        auto path = writeScreenshot(base, tracer_->readback(samples_), record);
        notice_ = "saved " + path.filename().replace_extension(".exr/.png").string();
        std::fprintf(stderr, "prism-view: saved %s (%u samples per pixel)\n", path.string().c_str(),
                     samples_);
    } catch (const Error &e) {
        notice_ = std::string("screenshot failed: ") + e.what();
        std::fprintf(stderr, "prism-view: %s\n", notice_.c_str());
    }
}

namespace {

// "4 spheres, 1 plane, 12176 triangles, 3 instances of 4968": the kinds the scene has, an
// instance count followed by the triangles its prototypes store.
std::string geometryText(const Scene &scene) {
    std::string text;
    auto add = [&](size_t count, const char *one, const char *many) {
        if (count == 0)
            return;
        text +=
            (text.empty() ? "" : ", ") + std::to_string(count) + " " + (count == 1 ? one : many);
    };
    add(scene.spheres.size(), "sphere", "spheres");
    add(scene.planes.size(), "plane", "planes");
    add(scene.triangles.size(), "triangle", "triangles");
    if (!scene.instances.empty())
        text += (text.empty() ? "" : ", ") + std::to_string(scene.instances.size()) +
                (scene.instances.size() == 1 ? " instance" : " instances") + " of " +
                std::to_string(scene.prototypeTriangleCount()) + " triangles";
    return text.empty() ? "nothing to hit" : text;
}

} // namespace

OverlayStats Viewer::overlayStats() const {
    OverlayStats s;
    s.fps = stats_.fps();
    s.msPerFrame = stats_.msPerFrame();
    s.mraysPerSecond = stats_.mraysPerSecond(); // like FPS, the last rate while tracing
    s.samples = samples_;
    s.samplesTarget = options_.samplesPerPixel;
    s.grid = toggles_.grid ? gridText(grid_) : "off (1 cell)";
    s.geometry = geometryText(scene_);
    for (const ArrayBytes &a : tracer_->sceneArrayBytes())
        s.sceneBytes += a.bytes;
    s.device = context_->deviceName();
    s.presentMode = vk::presentModeName(swapchain_->presentMode());
    s.width = tracer_->width();
    s.height = tracer_->height();
    s.traceScale = traceScale_;
    s.scene = options_.scenePath.filename().string();
    if (sceneAnimated(loaded_))
        s.frame =
            "frame " + formatNumber(frame_) + " of " + formatNumber(lastAnimatedFrame(loaded_));
    s.sceneError = sceneError_;
    s.loopCutPixels = minus(lastCounters_, accumulationBase_).loopCutPixels;
    s.notice = notice_;
    return s;
}

bool Viewer::finished(uint32_t frames) const {
    if (options_.benchmarkFrames > 0) // the path's length, whatever a driver says
        return frames >= kBenchmarkWarmupFrames + options_.benchmarkFrames;
    return driver_.done(frames, *this);
}

bool Viewer::interactiveRun() const {
    return options_.benchmarkFrames == 0 && !driver_.scripted();
}

void Viewer::requestWindowSize(uint32_t width, uint32_t height) {
    window_.requestSize(width, height);
}

bool Viewer::reloadSceneFrom(const std::filesystem::path &path) {
    source_ = SceneSource(path);
    return reloadScene();
}

bool Viewer::converged() const {
    return samples_ >= options_.samplesPerPixel && !swapchainDirty_;
}

int Viewer::run() {
    bool interactive = interactiveRun();
    BenchmarkReport report;
    Timer frameTimer, benchmarkTimer;
    std::vector<double> frameStarts;
    driver_.begin();
    uint32_t frame = 0;
    while (!window_.shouldClose()) {
        bool idle = samples_ >= options_.samplesPerPixel;
        if (interactive && idle)
            glfwWaitEventsTimeout(0.1); // converged: nothing to trace until something happens
        else
            glfwPollEvents();
        WindowEvents events = window_.takeEvents();
        double frameMs = frameTimer.elapsedMs();
        frameTimer.reset();

        driver_.beforeFrame(frame, *this);
        VkExtent2D size = window_.framebufferSize();
        if (size.width == 0 || size.height == 0) {
            glfwWaitEvents(); // minimised
            continue;
        }
        // The window's size is asked for every frame: resize events may come late or merged.
        if (swapchainDirty_ || size.width != swapchain_->extent().width ||
            size.height != swapchain_->extent().height)
            recreateSwapchain();

        if (interactive) {
            handleKeys(events.keysPressed);
            if (source_.changedOnDisk())
                reloadScene();
        } else {
            driver_.input(frame, *this);
        }
        updateCamera(frame, frameMs / 1000.0, events.scrollY);

        FeatureToggles wanted = toggles_;
        if (overlay_->build(overlayStats(), wanted, overlayVisible_))
            setFeatures(wanted);

        bool measured = options_.benchmarkFrames > 0 && frame >= kBenchmarkWarmupFrames;
        if (measured)
            frameStarts.push_back(benchmarkTimer.elapsedMs());
        if (measured && frameStarts.size() == 1)
            report.warmupMs = frameStarts.front();
        if (samples_ == 0)
            accumulationMs_ = 0.0;
        bool accumulating = traceScale_ == 1 && samples_ > 0; // not a first sample
        bool traced = drawFrame(measured);
        if (traced) {
            stats_.addFrame(frameMs);
            accumulationMs_ += frameMs;
            if (accumulating)
                fullFrameMs_ = frameMs;
        }
        driver_.afterFrame(frame);
        frame += 1;
        if (finished(frame))
            break;
    }
    drainFrames();

    if (options_.benchmarkFrames > 0) {
        frameStarts.push_back(benchmarkTimer.elapsedMs());
        for (size_t i = 0; i + 1 < frameStarts.size(); ++i)
            report.frameMs.push_back(frameStarts[i + 1] - frameStarts[i]);
        report.scene = options_.scenePath.string();
        report.device = context_->deviceName();
        report.presentMode = vk::presentModeName(swapchain_->presentMode());
        report.grid = gridText(grid_);
        report.width = tracer_->width();
        report.height = tracer_->height();
        report.depth = options_.maxDepth;
        report.loadMs = loadMs_;
        report.buildMs = gridBuildMs_;
        report.gridCache = gridCacheState_;
        report.objCacheHits = uint32_t(objCache_.hits);
        report.objCacheMisses = uint32_t(objCache_.misses);
        report.warmupFrames = kBenchmarkWarmupFrames;
        report.rays = benchmarkRays_;
        std::printf("%s\n", benchmarkJson(report).c_str());
        std::fflush(stdout);
    }
    driver_.end(frame, *this);
    if (context_->validationMessageCount() > 0) {
        std::fprintf(stderr, "prism-view: %u Vulkan validation messages (printed above)\n",
                     context_->validationMessageCount());
        return 1;
    }
    return 0;
}

} // namespace prism
