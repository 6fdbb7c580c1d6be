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

std::vector<BenchResult> runStudy(vk::Context &context, const std::vector<std::string> &scenes,
                                  const std::vector<BenchVariant> &variants,
                                  const BenchSettings &settings,
                                  const std::function<void(const std::string &)> &progress) {
    std::vector<BenchResult> all;
    for (const std::string &path : scenes) {
        Scene sourceScene = loadScene(path);
        if (!settings.keepOrigin)
            centerOnCamera(sourceScene);
        const Scene &scene = sourceScene;
        std::string name = std::filesystem::path(path).stem().string();
        std::vector<BenchResult> results;
        std::vector<std::unique_ptr<RayTracer>> tracers;
        std::vector<Grid> grids;
        std::optional<Scene> flat; // the scene with its instances written out, once
        std::vector<const Scene *> variantScenes;
        for (const BenchVariant &variant : variants) {
            progress(name + " " + variant.name + ": build + warm-up");
            if (variant.flattenInstances && !flat)
                flat = flattenInstances(sourceScene);
            const Scene &scene = variant.flattenInstances ? *flat : sourceScene;
            variantScenes.push_back(&scene);
            BenchResult r;
            r.scene = name;
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
            for (const ArrayBytes &a : tracer->sceneArrayBytes())
                r.sceneBytes += a.bytes;
            FrameResult warm = tracer->renderFrame(scene.camera, settings.samplesPerPixel);
            r.rays = warm.rays;
            if (!settings.imageDir.empty())
                saveImage(context, *tracer, settings,
                          std::filesystem::path(settings.imageDir) /
                              (name + "_" + variant.name + ".exr"));
            results.push_back(r);
            tracers.push_back(std::move(tracer));
            if (settings.profile)
                grids.push_back(std::move(grid));
        }
        std::unique_ptr<EmbreeBaseline> embree;
        if (settings.embreeBaseline) {
            progress(name + " embree: build + warm-up");
            embree = std::make_unique<EmbreeBaseline>(scene, settings.width, settings.height);
            BenchResult r;
            r.scene = name;
            r.variant = "embree";
            r.primitives = scene.finitePrimitiveCount() + scene.planes.size();
            r.grid = "BVH";
            r.buildMs = embree->build().commitMs;
            r.rays = embree->traceFrame().rays;
            results.push_back(r);
        }
        for (uint32_t run = 0; run < settings.runs; ++run) {
            for (size_t v = 0; v < variants.size(); ++v) {
                progress(name + " " + variants[v].name + ": frame " + std::to_string(run + 1) +
                         "/" + std::to_string(settings.runs));
                FrameResult f = tracers[v]->renderFrame(scene.camera, settings.samplesPerPixel);
                results[v].frameMs.push_back(f.gpuMs);
                results[v].wallMs.push_back(f.wallMs);
            }
            if (embree) {
                progress(name + " embree: frame " + std::to_string(run + 1) + "/" +
                         std::to_string(settings.runs));
                double ms = embree->traceFrame().ms;
                results.back().frameMs.push_back(ms);
                results.back().wallMs.push_back(ms);
            }
        }
        for (size_t v = 0; v < variants.size() && settings.profile; ++v) {
            progress(name + " " + variants[v].name + ": profile");
            results[v].profile =
                profileVariant(context, *variantScenes[v], grids[v], variants[v], settings);
        }
        all.insert(all.end(), results.begin(), results.end());
    }
    return all;
}

} // namespace prism
