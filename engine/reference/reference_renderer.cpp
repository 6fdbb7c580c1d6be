#include "reference/reference_renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/error.h"
#include "reference/scene_query.h"
#include "shared/sampling.h"
#include "reference/surface_reference.h"
#include "reference/trace_reference.h"
#include "scene/instance_flattening.h"
#include "scene/scene_origin.h"

namespace prism {
namespace {

void validate(const Scene &scene, const RenderSettings &settings) {
    if (settings.width <= 0 || settings.height <= 0)
        throw Error("reference renderer: image size " + std::to_string(settings.width) + "x" +
                    std::to_string(settings.height) + " is not positive");
    if (settings.samplesPerPixel == 0)
        throw Error("reference renderer: samples per pixel must be at least 1");
    if (settings.maxDepth == 0)
        throw Error("reference renderer: maximum ray depth must be at least 1");
    auto checkMaterial = [&](uint32_t material, const char *what, size_t index) {
        if (material >= scene.materials.size())
            throw Error("reference renderer: " + std::string(what) + " " + std::to_string(index) +
                        " uses material " + std::to_string(material) + " of " +
                        std::to_string(scene.materials.size()));
    };
    for (size_t i = 0; i < scene.spheres.size(); ++i)
        checkMaterial(scene.spheres[i].material, "sphere", i);
    for (size_t i = 0; i < scene.planes.size(); ++i)
        checkMaterial(scene.planes[i].material, "plane", i);
    for (size_t i = 0; i < scene.triangles.size(); ++i)
        checkMaterial(scene.triangles[i].material, "triangle", i);
    for (const Material &m : scene.materials) {
        if (m.texture == kNoTexture)
            continue;
        if (m.texture < 0 || size_t(m.texture) >= scene.textures.size())
            throw Error("reference renderer: material '" + m.name + "' uses texture " +
                        std::to_string(m.texture) + " of " + std::to_string(scene.textures.size()));
        const Texture &t = scene.textures[size_t(m.texture)];
        if (t.width <= 0 || t.height <= 0 || t.texels.size() != size_t(t.width) * size_t(t.height))
            throw Error("reference renderer: texture '" + t.path + "' has " +
                        std::to_string(t.texels.size()) + " texels for " + std::to_string(t.width) +
                        "x" + std::to_string(t.height));
    }
}

// Depth and normal AOVs from the pixel-centre primary ray (as the shader writes them).
void writeAov(const Scene &scene, const CameraFrame &frame, int px, int py, float &depth,
              glm::vec3 &normal) {
    Ray ray = cameraRay(frame, glm::dvec2(px, py) + 0.5);
    reference::Hit hit;
    if (!reference::traceClosest(scene, ray, std::numeric_limits<double>::infinity(), hit)) {
        depth = std::numeric_limits<float>::infinity();
        normal = glm::vec3(0.0f);
        return;
    }
    glm::dvec3 ng = reference::surfaceAt(scene, ray, hit).geometricNormal;
    depth = float(hit.t);
    normal = glm::vec3(glm::dot(ng, ray.dir) > 0.0 ? -ng : ng);
}

void renderRow(const Scene &scene, const RenderSettings &settings, const CameraFrame &frame, int py,
               RenderedImage &image, RayCounts &rays) {
    for (int px = 0; px < settings.width; ++px) {
        size_t pixel = size_t(py) * size_t(settings.width) + size_t(px);
        glm::dvec3 sum(0.0);
        for (uint32_t sample = 0; sample < settings.samplesPerPixel; ++sample)
            sum += tracePixelSample(scene, frame, px, py, sample, settings.samplesPerPixel,
                                    settings.maxDepth, rays, settings.seed);
        image.rgba[pixel] = glm::vec4(glm::vec3(sum / double(settings.samplesPerPixel)), 1.0f);
        writeAov(scene, frame, px, py, image.depth[pixel], image.normal[pixel]);
    }
}

} // namespace

glm::dvec3 tracePixelSample(const Scene &scene, const CameraFrame &frame, int px, int py,
                            uint32_t sampleIndex, uint32_t spp, uint32_t maxDepth,
                            RayCounts &rays, uint32_t seed) {
    uint32_t pixelIndex = gpu::samplingKey(uint32_t(py) * uint32_t(frame.width) + uint32_t(px), seed);
    Ray ray = cameraRay(frame, pixelSamplePosition(px, py, pixelIndex, sampleIndex, spp));
    rays.primary += 1;
    return reference::traceRadiance(scene, ray, {pixelIndex, sampleIndex, spp}, maxDepth, rays);
}

RenderedImage renderReference(const Scene &given, const RenderSettings &settings,
                              const std::function<void(double)> &progress) {
    // Ray offsets are relative to |P| (as on the GPU), so the reference too works relative to
    // the camera; in double the move itself costs nothing measurable (scene_origin.h). Instances
    // become plain triangles: the reference has one level, the tracer two.
    std::optional<Scene> moved;
    if (given.camera.eye != glm::dvec3(0.0) || !given.instances.empty()) {
        moved = flattenInstances(given);
        moveOrigin(*moved, given.camera.eye);
    }
    const Scene &scene = moved ? *moved : given;
    validate(scene, settings);
    RenderedImage image;
    image.width = settings.width;
    image.height = settings.height;
    size_t pixels = size_t(settings.width) * size_t(settings.height);
    image.rgba.resize(pixels);
    image.depth.resize(pixels);
    image.normal.resize(pixels);
    CameraFrame frame = makeCameraFrame(settings.camera.value_or(scene.camera), settings.width,
                                        settings.height);

    // Workers take rows from a shared counter; every pixel depends only on its own indices, so
    // the image is the same whatever thread renders which row.
    unsigned threadCount = std::max(1u, std::thread::hardware_concurrency());
    threadCount = std::min(threadCount, unsigned(settings.height));
    std::atomic<int> nextRow{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::condition_variable rowDone;
    int rowsDone = 0;
    std::exception_ptr error;
    std::vector<RayCounts> counts(threadCount);
    auto work = [&](unsigned worker) {
        try {
            for (int row = nextRow++; row < settings.height && !failed; row = nextRow++) {
                renderRow(scene, settings, frame, row, image, counts[worker]);
                std::lock_guard lock(mutex);
                ++rowsDone;
                rowDone.notify_one();
            }
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!error)
                error = std::current_exception();
            failed = true;
            rowDone.notify_one();
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(threadCount);
    for (unsigned t = 0; t < threadCount; ++t)
        threads.emplace_back(work, t);

    // The caller reports progress, so the callback never runs on a worker thread.
    int reported = -1;
    {
        std::unique_lock lock(mutex);
        while (rowsDone < settings.height && !failed) {
            rowDone.wait_for(lock, std::chrono::milliseconds(100));
            if (progress && rowsDone != reported) {
                reported = rowsDone;
                double fraction = double(rowsDone) / double(settings.height);
                lock.unlock();
                progress(fraction);
                lock.lock();
            }
        }
    }
    for (std::thread &t : threads)
        t.join();
    if (error)
        std::rethrow_exception(error);
    for (const RayCounts &c : counts) {
        image.rays.primary += c.primary;
        image.rays.shadow += c.shadow;
        image.rays.secondary += c.secondary;
    }
    if (progress && reported != settings.height)
        progress(1.0);
    return image;
}

} // namespace prism
