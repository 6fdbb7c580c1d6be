#include "frame_sources.h"

#include "core/error.h"
#include "core/timer.h"
#include "reference/reference_renderer.h"
#include "tile_tint.h"

namespace prism {
namespace {

// A region's image says where it lies in the whole (an EXR's data window).
void placeRegion(OutputImage &image, const RenderOptions &o) {
    if (o.region.empty())
        return;
    image.x = int(o.region.x0);
    image.y = int(o.region.y0);
    image.fullWidth = int(o.width);
    image.fullHeight = int(o.height);
}

// The pixels of `r` in a whole image, every channel.
OutputImage cutRegion(const OutputImage &whole, const PixelRect &r) {
    OutputImage part;
    part.width = int(r.width());
    part.height = int(r.height());
    auto cut = [&](const std::vector<float> &from, std::vector<float> &to, size_t channels) {
        if (from.empty())
            return;
        for (uint32_t y = r.y0; y < r.y1; ++y) {
            auto row = from.begin() + std::ptrdiff_t((size_t(y) * whole.width + r.x0) * channels);
            to.insert(to.end(), row, row + std::ptrdiff_t(r.width() * channels));
        }
    };
    cut(whole.rgba, part.rgba, 4);
    cut(whole.depth, part.depth, 1);
    cut(whole.normal, part.normal, 3);
    return part;
}

} // namespace

ContextInBackground::ContextInBackground(const RenderOptions &o, const DiskCache *pipelineStore) {
    vk::ContextOptions options;
    options.validation = o.validation;
    options.deviceNameFilter = o.deviceFilter;
    options.pipelineStore = pipelineStore;
    auto ended = std::make_shared<std::promise<void>>();
    ended_ = ended->get_future().share();
    made_ = std::async(std::launch::async, [options, ended] {
        // Set however the making ends, so that no waiter waits for ever.
        struct Signal {
            std::promise<void> &ended;
            ~Signal() { ended.set_value(); }
        } signal{*ended};
        Timer timer;
        auto context = std::make_unique<vk::Context>(options);
        return std::pair{std::move(context), timer.elapsedMs()};
    });
}

vk::Context &ContextInBackground::get(double &waitedMs, double &madeMs) {
    Timer wait;
    if (!context_) {
        auto [context, ms] = made_.get();
        context_ = std::move(context);
        madeMs = ms;
    }
    waitedMs = wait.elapsedMs();
    return *context_;
}

VulkanFrameSource::VulkanFrameSource(const RenderOptions &o, const Scene &scene, const Grid &grid,
                                     const SceneExtent *extent, ContextInBackground &background,
                                     const Camera &firstCamera)
    : o_(o) {
    context_ = &background.get(phases_.contextMs, phases_.contextMadeMs);
    TracerOptions tracerOptions;
    tracerOptions.maxDepth = o.maxDepth;
    tracerOptions.writeAov = o.aovDepth || o.aovNormal;
    tracerOptions.region = o.region;
    tracerOptions.extent = extent;
    Timer phase;
    tracer_ = std::make_unique<RayTracer>(*context_, scene, grid, o.width, o.height, tracerOptions);
    tracer_->setSeed(o.seed);
    phases_.tracerMs = phase.elapsedMs();
    // lavapipe compiles the shader inside the first dispatch: one 8x8 tile takes that out of
    // the timed frames.
    phase.reset();
    tracer_->compile(firstCamera);
    phases_.compileMs = phase.elapsedMs();
}

FrameOutcome VulkanFrameSource::render(const Camera &camera, const std::string &label,
                                       const std::string &after, ProgressLine &progress) {
    FrameOutcome out;
    Timer phase;
    // Timing several frames (--runs) also gets a warm-up frame, so that they are alike
    // (caches, clocks); a single render does not pay a second frame for that.
    for (uint32_t frame = o_.repeat > 1 ? 0 : 1; frame <= o_.repeat; ++frame) {
        std::string text = frame == 0      ? label + " warm-up"
                           : o_.repeat > 1 ? label + " timing " + std::to_string(frame) + "/" +
                                                 std::to_string(o_.repeat)
                                           : label;
        Timer frameTimer; // the rate so far: the shader's ray counts over the frame's time
        auto report = [&](double f) {
            double ms = frameTimer.elapsedMs();
            double rate = ms > 0.0 ? double(tracer_->raysCounted()) / (ms * 1e3) : 0.0;
            progress.update(text, f, after, rate);
        };
        FrameResult result =
            tracer_->renderFrame(camera, frame == 0 ? 1u : o_.samplesPerPixel, report,
                                 frame == o_.repeat); // the image read back below
        // renderFrame traces a frame that overran lavapipe's loop limit again, resumably.
        out.resumeDispatches = result.resumeDispatches;
        out.tiles = result.tiles;
        if (frame > 0) {
            out.frameMs.push_back(result.gpuMs);
            out.wallMs.push_back(result.wallMs);
        }
        out.rays = result.rays;
    }
    out.framesMs = phase.elapsedMs();
    phase.reset();
    TracedImage traced = tracer_->readback(o_.samplesPerPixel);
    out.readbackMs = phase.elapsedMs();
    if (context_->validationMessageCount() > 0)
        throw Error(std::to_string(context_->validationMessageCount()) +
                    " Vulkan validation messages (printed above); refusing to write the image");
    out.image.width = int(traced.width);
    out.image.height = int(traced.height);
    out.image.rgba = std::move(traced.rgba);
    if (o_.showTiles)
        tintTilesByClass(
            out.image.rgba, wholeImage(traced.fullWidth, traced.fullHeight),
            PixelRect{traced.x0, traced.y0, traced.x0 + traced.width, traced.y0 + traced.height},
            tracer_->lastTileClasses());
    if (o_.aovDepth)
        out.image.depth = std::move(traced.depth);
    if (o_.aovNormal)
        out.image.normal = std::move(traced.normal);
    placeRegion(out.image, o_);
    return out;
}

FrameOutcome CpuFrameSource::render(const Camera &camera, const std::string &label,
                                    const std::string &after, ProgressLine &progress) {
    RenderSettings settings;
    settings.width = int(o_.width);
    settings.height = int(o_.height);
    settings.samplesPerPixel = o_.samplesPerPixel;
    settings.maxDepth = o_.maxDepth;
    settings.seed = o_.seed;
    settings.camera = camera;
    FrameOutcome out;
    RenderedImage rendered;
    Timer phase;
    for (uint32_t frame = 1; frame <= o_.repeat; ++frame) {
        std::string text = o_.repeat > 1 ? label + " timing " + std::to_string(frame) + "/" +
                                               std::to_string(o_.repeat)
                                         : label;
        Timer timer;
        rendered =
            renderReference(scene_, settings, [&](double f) { progress.update(text, f, after); });
        out.frameMs.push_back(timer.elapsedMs());
        out.wallMs.push_back(out.frameMs.back());
    }
    out.framesMs = phase.elapsedMs();
    out.rays = rendered.rays;
    out.image.width = rendered.width;
    out.image.height = rendered.height;
    out.image.rgba.reserve(rendered.rgba.size() * 4);
    for (const glm::vec4 &p : rendered.rgba)
        out.image.rgba.insert(out.image.rgba.end(), {p.r, p.g, p.b, p.a});
    if (o_.aovDepth)
        out.image.depth = rendered.depth;
    if (o_.aovNormal)
        for (const glm::vec3 &n : rendered.normal)
            out.image.normal.insert(out.image.normal.end(), {n.x, n.y, n.z});
    // The reference traces every pixel on its own: a region is the whole image cut.
    if (!o_.region.empty()) {
        out.image = cutRegion(out.image, o_.region);
        placeRegion(out.image, o_);
    }
    return out;
}

} // namespace prism
