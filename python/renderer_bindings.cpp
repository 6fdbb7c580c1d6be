// prism.Renderer: the Vulkan device, and the tracer of the last scene and settings rendered.
#include <cmath>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cache/disk_cache.h"
#include "core/timer.h"
#include "render/ray_tracer.h"
#include "session/render_stats.h"
#include "shared/gpu_types.h"
#include "vk/context.h"

namespace py = pybind11;

namespace prism::python {
namespace {

// What a tracer is made for: the scene (its every frame: PyScene::lineage) and everything fixed
// at its creation.
struct TracerKey {
    uint64_t scene = 0;
    uint32_t width = 0, height = 0, depth = 0;
    bool aov = false;
    bool operator==(const TracerKey &) const = default;
};

// A JSON value as the Python object json.loads would make of its text, built directly (the text
// and its parse cost a loop of small renders 0.1 ms a read of last_stats).
py::object toPython(const nlohmann::json &value) {
    switch (value.type()) {
    case nlohmann::json::value_t::object: {
        py::dict dict;
        for (const auto &[key, item] : value.items())
            dict[py::str(key)] = toPython(item);
        return dict;
    }
    case nlohmann::json::value_t::array: {
        py::list list;
        for (const nlohmann::json &item : value)
            list.append(toPython(item));
        return list;
    }
    case nlohmann::json::value_t::string:
        return py::str(value.get_ref<const std::string &>());
    case nlohmann::json::value_t::boolean:
        return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer:
        return py::int_(value.get<int64_t>());
    case nlohmann::json::value_t::number_unsigned:
        return py::int_(value.get<uint64_t>());
    case nlohmann::json::value_t::number_float: // not finite: null in the text, so None
        return std::isfinite(value.get<double>()) ? py::object(py::float_(value.get<double>()))
                                                  : py::object(py::none());
    default:
        return py::none();
    }
}

class PyRenderer {
public:
    PyRenderer(const std::optional<std::string> &device, bool validation, bool cache) {
        vk::ContextOptions options;
        options.validation = validation;
        options.deviceNameFilter = device.value_or("");
        // The device's pipeline cache and the tracer's folded modules kept where prism-render
        // keeps them (cache/disk_cache.h), so a script's first render does not fold again.
        if (std::filesystem::path directory = DiskCache::defaultDirectory();
            cache && !directory.empty()) {
            store_ = std::make_unique<DiskCache>(DiskCacheOptions{directory});
            options.pipelineStore = store_.get();
        }
        py::gil_scoped_release released;
        context_ = std::make_unique<vk::Context>(options);
    }
    ~PyRenderer() {
        if (context_ && store_) // the driver's cache, for the next script (a GPU's compile)
            context_->savePipelineCache();
    }

    py::dict render(const std::shared_ptr<PyScene> &scene, uint32_t width, uint32_t height,
                    uint32_t spp, uint32_t depth, uint32_t seed,
                    const std::vector<std::string> &aovs) {
        if (width == 0 || height == 0 || width > 16384 || height > 16384)
            throw py::value_error("width and height must be 1 to 16384, got " +
                                  std::to_string(width) + "x" + std::to_string(height));
        if (spp == 0 || spp > kMaxSamplesPerPixel)
            throw py::value_error("spp must be 1 to " + std::to_string(kMaxSamplesPerPixel) +
                                  ", got " + std::to_string(spp));
        if (depth == 0 || depth > 16)
            throw py::value_error("depth must be 1 to 16, got " + std::to_string(depth));
        if (seed > gpu::kMaxSeed)
            throw py::value_error("seed must be 0 to " + std::to_string(gpu::kMaxSeed) + ", got " +
                                  std::to_string(seed));
        bool rgb = false, z = false, n = false;
        for (const std::string &a : aovs) {
            bool &wanted = a == "rgb" ? rgb : a == "z" ? z : n;
            if (a != "rgb" && a != "z" && a != "n")
                throw py::value_error("aovs are 'rgb', 'z' and 'n', got '" + a + "'");
            wanted = true;
        }
        // The arrays first, while this thread holds the GIL: the readback writes straight into
        // them (one pass over the pixels, no copy of a TracedImage).
        Timer arrays;
        py::dict out;
        ReadbackTargets targets;
        auto array = [&](const char *name, size_t channels) {
            py::array_t<float> a({size_t(height), size_t(width), channels});
            out[name] = a;
            return static_cast<float *>(a.mutable_data());
        };
        if (rgb)
            targets.rgb = array("rgb", 3);
        if (z)
            targets.depth = array("z", 1);
        if (n)
            targets.normal = array("n", 3);
        double arraysMs = arrays.elapsedMs();
        FrameResult frame;
        double tracerMs = 0.0, readbackMs = 0.0;
        std::vector<ArrayBytes> sceneArrays;
        Camera camera = scene->camera;
        // Taken while the GIL is held: a frame set from another Python thread meanwhile swaps
        // scene->prepared, and the tracer's scene, grid and extent must come from one.
        std::shared_ptr<const PreparedScene> prepared = scene->prepared;
        uint32_t messagesBefore = context_->validationMessageCount();
        {
            py::gil_scoped_release released; // Python threads run while this one renders
            std::lock_guard lock(mutex_);    // one render at a time on this renderer
            TracerKey key{scene->lineage, width, height, depth, z || n};
            if (!tracer_ || !(key == key_)) {
                tracer_.reset(); // the old scene's arrays go before the new ones come
                Timer made;
                TracerOptions options;
                options.maxDepth = depth;
                options.writeAov = key.aov;
                const std::optional<SceneExtent> &extent = prepared->extent;
                options.extent = extent ? &*extent : nullptr;
                tracer_ = std::make_unique<RayTracer>(*context_, prepared->scene, prepared->grid,
                                                      width, height, options);
                tracerMs = made.elapsedMs();
                key_ = key;
                keptScene_ = prepared; // the tracer's scene stays alive with it
            } else if (keptScene_ != prepared) {
                // The same scene at another frame: its instances moved (scene.frame).
                Timer moved;
                tracer_->setScene(prepared->scene, prepared->grid);
                tracerMs = moved.elapsedMs();
                keptScene_ = prepared;
            }
            tracer_->setSeed(seed);
            frame = tracer_->renderFrame(camera, spp, {}, true); // copied out in its submission
            Timer readback;
            tracer_->readbackInto(spp, targets);
            readbackMs = readback.elapsedMs();
            sceneArrays = tracer_->sceneArrayBytes();
        }
        if (context_->validationMessageCount() != messagesBefore)
            throw std::runtime_error(
                std::to_string(context_->validationMessageCount() - messagesBefore) +
                " Vulkan validation messages (printed on stderr) during this render");
        // The names of prism-render --stats (session/render_stats.h), less what only a
        // command's run has (walk counts, writes, the process's phases).
        nlohmann::json stats = {
            {"scene", scene->path},
            {"backend", "vulkan"},
            {"device", context_->deviceName()},
            {"width", width},
            {"height", height},
            {"region", "0," + std::to_string(width) + ",0," + std::to_string(height)},
            {"spp", spp},
            {"depth", depth},
            {"seed", seed},
            {"load_ms", scene->loadMs},
            {"trace_ms", frame.gpuMs},
            {"trace_ms_median", frame.gpuMs},
            {"wall_ms", frame.wallMs},
            {"wall_ms_median", frame.wallMs},
            {"frames", 1},
            {"tiles", tileStats(frame.tiles)},
            {"scene_gpu_bytes", gpuBytesStats(sceneArrays)},
            {"phases_ms",
             {{"tracer", tracerMs}, // 0: kept from the last render
              {"frames", frame.wallMs},
              {"readback", readbackMs},
              {"arrays", arraysMs}}}};
        stats.update(sceneStats(*scene->prepared));
        stats.update(frameStats(frame.rays, frame.gpuMs, frame.resumeDispatches));
        lastStats_ = std::move(stats);
        lastStatsDict_ = py::none(); // made when asked for: a loop that never looks pays nothing
        return out;
    }

    std::string device() const { return context_->deviceName(); }
    py::object lastStats() {
        if (lastStatsDict_.is_none())
            lastStatsDict_ = toPython(lastStats_);
        return lastStatsDict_;
    }

private:
    std::unique_ptr<DiskCache> store_; // before context_, which keeps its pipelines in it
    std::unique_ptr<vk::Context> context_;
    std::mutex mutex_;
    TracerKey key_;
    std::shared_ptr<const PreparedScene> keptScene_;
    std::unique_ptr<RayTracer> tracer_; // destroyed before the context (declared after it)
    nlohmann::json lastStats_ = nlohmann::json::object();
    py::object lastStatsDict_ = py::none();
};

} // namespace

void bindRenderer(py::module_ &m) {
    py::class_<PyRenderer>(
        m, "Renderer",
        "Owns a Vulkan device and, for the last scene and settings rendered, the scene's GPU "
        "arrays and compiled tracer: renders of the same scene at the same size, depth and "
        "AOVs reuse them (a camera or frame change does not rebuild anything). Renders run "
        "with the GIL released.")
        .def(py::init<const std::optional<std::string> &, bool, bool>(),
             py::arg("device") = py::none(), py::arg("validation") = false, py::arg("cache") = true,
             "device: the first Vulkan device whose name contains this text (None: a discrete "
             "GPU if there is one, else lavapipe); validation: Vulkan validation layers, a "
             "message then fails the render; cache: keep the device's pipeline cache and the "
             "tracer's specialized modules in prism.load's cache directory "
             "($PRISM_CACHE_DIR, else ~/.cache/prism) and read them back.")
        .def("render", &PyRenderer::render, py::arg("scene"), py::arg("width") = 640,
             py::arg("height") = 480, py::arg("spp") = 1, py::arg("depth") = 5, py::arg("seed") = 0,
             py::arg("aovs") = std::vector<std::string>{"rgb"},
             "Renders `scene` through its camera. Returns a dict of float32 NumPy arrays, "
             "C-contiguous, height x width x channels, row 0 at the top: 'rgb' (linear "
             "radiance, not clamped), 'z' (distance along the pixel's centre ray, inf on a "
             "miss), 'n' (unit geometric normal facing the ray, 0 on a miss), those named in "
             "`aovs`. The same image as prism-render's EXR for the same options, bit for bit. "
             "seed: the sampling seed (0 to 16777215; 0 draws what prism-render draws without "
             "--seed): another seed draws another independent set of samples.")
        .def_property_readonly("device", &PyRenderer::device, "The Vulkan device's name.")
        .def_property_readonly(
            "last_stats", &PyRenderer::lastStats,
            "The last render's figures, a dict with prism-render --stats' names "
            "(docs/python.md): trace_ms (GPU timestamps), wall_ms, rays {primary, shadow, "
            "secondary}, mrays_per_s, tiles, the grid's and the scene's figures, "
            "scene_gpu_bytes, phases_ms {tracer (0: the tracer was kept), frames, readback, "
            "arrays}, and the settings.");
}

} // namespace prism::python
