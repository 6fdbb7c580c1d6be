// prism.Scene, prism.Camera and prism.load.
#include <array>
#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cache/disk_cache.h"
#include "core/timer.h"
#include "scene/camera_animation.h"
#include "scene/placement_animation.h"
#include "scene/scene_loader.h"

namespace py = pybind11;

namespace prism::python {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 tuple(const glm::dvec3 &v) {
    return {v.x, v.y, v.z};
}
glm::dvec3 vec(const Vec3 &v) {
    return {v[0], v[1], v[2]};
}

// build: 'full' or 'lean' (GridOptions::effort). prism-render's 'auto' decides by the image's
// samples, which a scene rendered any number of times at any size does not know.
GridOptions::Effort parseBuild(const std::string &build) {
    if (build != "full" && build != "lean")
        throw py::value_error("build must be 'full' (fastest rays, for many renders) or 'lean' "
                              "(half the build and a third of a big mesh's memory, slower "
                              "rays), got '" +
                              build + "'");
    return parseGridBuild(build);
}

std::shared_ptr<PyScene> prepare(Scene loaded, const std::string &grid, const std::string &build,
                                 bool cache, const std::string &path, double loadMs) {
    GridOptions options = parseGridOption(grid);
    options.effort = parseBuild(build);
    std::optional<DiskCache> store;
    if (cache)
        store.emplace(DiskCacheOptions{DiskCache::defaultDirectory()});
    auto scene = std::make_shared<PyScene>();
    {
        py::gil_scoped_release released; // the grid's build may take seconds
        scene->prepared = std::make_shared<const PreparedScene>(
            prepareScene(std::move(loaded), options, store ? &*store : nullptr));
    }
    scene->camera = scene->prepared->scene.camera;
    static std::atomic<uint64_t> loads{0};
    scene->lineage = ++loads;
    scene->path = path;
    scene->loadMs = loadMs;
    return scene;
}

// scene.camera: a view of the scene's camera, in the file's coordinates, that writes through
// (scene.camera.fov = 40 changes the scene's next render).
struct PyCamera {
    std::shared_ptr<PyScene> scene;
    glm::dvec3 origin() const { return scene->prepared->scene.origin; }
};

} // namespace

void bindScene(py::module_ &m) {
    py::class_<PyCamera>(m, "Camera",
                         "The camera of a Scene (scene.camera), in the scene file's coordinates. "
                         "Setting a field changes the scene's next render.")
        .def_property(
            "eye", [](const PyCamera &c) { return tuple(c.scene->camera.eye + c.origin()); },
            [](PyCamera &c, const Vec3 &v) { c.scene->camera.eye = vec(v) - c.origin(); },
            "Where the camera is: (x, y, z).")
        .def_property(
            "look", [](const PyCamera &c) { return tuple(c.scene->camera.look + c.origin()); },
            [](PyCamera &c, const Vec3 &v) { c.scene->camera.look = vec(v) - c.origin(); },
            "The point the camera looks at: (x, y, z).")
        .def_property(
            "up",
            [](const PyCamera &c) {
                glm::vec3 u = c.scene->camera.up;
                return Vec3{u.x, u.y, u.z};
            },
            [](PyCamera &c, const Vec3 &v) { c.scene->camera.up = glm::vec3(vec(v)); },
            "The up direction: (x, y, z).")
        .def_property(
            "fov", [](const PyCamera &c) { return c.scene->camera.fovDegrees; },
            [](PyCamera &c, float degrees) {
                if (!(degrees > 0.0f && degrees < 180.0f))
                    throw py::value_error("fov must be between 0 and 180 degrees");
                c.scene->camera.fovDegrees = degrees;
            },
            "The vertical field of view in degrees (perspective cameras).")
        .def_property_readonly(
            "ortho_height", [](const PyCamera &c) { return c.scene->camera.orthoHeight; },
            "The image plane's height of a parallel camera; 0 for a perspective one.")
        .def(
            "look_at",
            [](PyCamera &c, const Vec3 &eye, const Vec3 &target, const Vec3 &up) {
                if (eye == target)
                    throw py::value_error("look_at: eye and target must differ");
                if (up == Vec3{0.0, 0.0, 0.0})
                    throw py::value_error("look_at: up must not be zero");
                c.scene->camera.eye = vec(eye) - c.origin();
                c.scene->camera.look = vec(target) - c.origin();
                c.scene->camera.up = glm::vec3(vec(up));
            },
            py::arg("eye"), py::arg("target"), py::arg("up") = Vec3{0.0, 1.0, 0.0},
            "Puts the camera at `eye`, looking at `target`, with `up` up.")
        .def("__repr__", [](const PyCamera &c) {
            glm::dvec3 e = c.scene->camera.eye + c.origin(), l = c.scene->camera.look + c.origin();
            return "prism.Camera(eye=(" + std::to_string(e.x) + ", " + std::to_string(e.y) + ", " +
                   std::to_string(e.z) + "), look=(" + std::to_string(l.x) + ", " +
                   std::to_string(l.y) + ", " + std::to_string(l.z) +
                   "), fov=" + std::to_string(c.scene->camera.fovDegrees) + ")";
        });

    py::class_<PyScene, std::shared_ptr<PyScene>>(
        m, "Scene",
        "A scene loaded and made ready to render (centred on its camera, its grid built): "
        "prism.load(path) or Scene.from_string(text). Render it with a prism.Renderer.")
        .def_static(
            "from_string",
            [](const std::string &text, const std::string &base_dir, const std::string &grid,
               const std::string &build, bool cache) {
                // Paths in the text (meshes, textures) resolve against base_dir.
                Timer load;
                Scene loaded = parseScene(text, std::filesystem::path(base_dir) / "<string>.scene");
                return prepare(std::move(loaded), grid, build, cache, "<string>", load.elapsedMs());
            },
            py::arg("text"), py::arg("base_dir") = ".", py::arg("grid") = "auto",
            py::arg("build") = "full", py::arg("cache") = true,
            "A scene from the text of a .scene file (docs/scene-format.md); paths in it "
            "resolve against base_dir. grid, build and cache as for prism.load. Raises "
            "SceneError.")
        .def_property_readonly(
            "camera", [](const std::shared_ptr<PyScene> &s) { return PyCamera{s}; },
            "The camera the next render uses (prism.Camera, writable fields).")
        .def_property(
            "frame", [](const PyScene &s) { return s.frame; },
            [](PyScene &s, double frame) {
                // The camera and instances prism-render --frames uses for this frame, to the bit.
                Camera camera = cameraAt(s.prepared->scene, frame);
                if (placementsAnimated(s.prepared->scene) && frame != s.prepared->frame) {
                    std::shared_ptr<const PreparedScene> current = s.prepared;
                    std::shared_ptr<PreparedScene> moved;
                    {
                        py::gil_scoped_release released; // the copy and the build take a while
                        moved = std::make_shared<PreparedScene>(*current);
                        moveToFrame(*moved, frame);
                    }
                    s.prepared = std::move(moved); // with the GIL: other threads read it
                }
                s.camera = camera;
                s.frame = frame;
            },
            "The animation frame (1 = the camera line). Setting it sets the camera to that "
            "frame's (key lines or a turntable) and moves keyed instances (key lines under "
            "place lines) there, docs/scene-format.md.")
        .def_property_readonly(
            "animated", [](const PyScene &s) { return sceneAnimated(s.prepared->scene); },
            "Whether the scene's camera or any instance moves (key lines or a turntable).")
        .def_property_readonly(
            "last_frame", [](const PyScene &s) { return lastAnimatedFrame(s.prepared->scene); },
            "The animation's last frame: the later of a turntable's frame count and the last "
            "key's frame (the camera's or a placement's), or 1 for a still scene. Frames run "
            "from 1.")
        .def_property_readonly(
            "primitives", [](const PyScene &s) { return s.prepared->scene.finitePrimitiveCount(); },
            "Finite primitives (triangles and spheres) as the grid holds them.")
        .def_property_readonly(
            "warnings", [](const PyScene &s) { return s.prepared->scene.warnings; },
            "What the loader warned about (FILE:LINE: text), as prism-render prints it.")
        .def_property_readonly(
            "grid_cache", [](const PyScene &s) { return s.prepared->gridCache.state; },
            "Whether the grid came from the grid cache: 'hit', 'miss' or 'off'.");

    m.def(
        "load",
        [](const std::string &path, const std::string &grid, const std::string &build, bool cache) {
            Timer load;
            Scene loaded = [&] {
                py::gil_scoped_release released; // big OBJ files take seconds
                // Big OBJ files parsed once, read back after (scene/obj_cache.h).
                std::optional<DiskCache> store;
                if (std::filesystem::path dir = DiskCache::defaultDirectory();
                    cache && !dir.empty())
                    store.emplace(DiskCacheOptions{dir});
                ObjCacheUse objCache{store ? &*store : nullptr};
                return loadScene(path, {}, &objCache);
            }();
            return prepare(std::move(loaded), grid, build, cache, path, load.elapsedMs());
        },
        py::arg("path"), py::arg("grid") = "auto", py::arg("build") = "full",
        py::arg("cache") = true,
        "Loads a .scene file (docs/scene-format.md) and builds its grid: grid is 'auto', "
        "'regular', 'adaptive', 'off', 'N' or 'NxNyNz' as prism-render --grid; build is "
        "'full' (the fastest rays: for a scene rendered many times) or 'lean' (half the build "
        "and a third of a big mesh's device memory, rays up to 1.7x slower at a million "
        "triangles: for one image), as prism-render --grid-build; with cache, grids are kept "
        "in and read from the grid cache ($PRISM_CACHE_DIR, else ~/.cache/prism). Raises "
        "SceneError for a bad file, ValueError for a bad argument.");
}

} // namespace prism::python
