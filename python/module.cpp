// `import prism`: Prism's renderer from Python (issue 33). This file: the module, its errors
// and prism.load; scene_bindings.cpp and renderer_bindings.cpp: the classes.
#include <string>

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "core/error.h"

namespace py = pybind11;

namespace {

// "FILE:LINE: message" without its place.
std::string messageOf(const prism::FileError &e) {
    std::string what = e.what();
    std::string place = e.file() + ":" + std::to_string(e.line()) + ": ";
    return what.rfind(place, 0) == 0 ? what.substr(place.size()) : what;
}

} // namespace

PYBIND11_MODULE(prism, m) {
    m.doc() = "Prism: a Whitted ray tracer on Vulkan (a GPU, or lavapipe on the CPU).\n\n"
              "    scene = prism.load('assets/scenes/showcase.scene')\n"
              "    renderer = prism.Renderer()\n"
              "    image = renderer.render(scene, 640, 480, spp=4)['rgb']  # H x W x 3 float32\n\n"
              "A Renderer keeps its Vulkan device and, for a scene at one size and set of "
              "options, the scene's GPU arrays and compiled tracer, so a loop of renders pays "
              "for them once. Images are linear radiance, not clamped. docs/python.md has the "
              "whole API.";
    m.attr("__version__") = PRISM_VERSION;

    // A bad scene file: .file, .line and .message say where and what (str() has them all).
    static py::exception<prism::FileError> sceneError(m, "SceneError");
    sceneError.doc() = "A scene, OBJ or MTL file Prism cannot read: .file, .line (from 1) and "
                       ".message say where and what; str() is 'FILE:LINE: message'.";
    py::register_exception_translator([](std::exception_ptr caught) {
        try {
            if (caught)
                std::rethrow_exception(caught);
        } catch (const prism::FileError &e) {
            // An instance of the class (py::exception's own call would only set the error).
            py::object error = py::handle(sceneError.ptr())(e.what());
            error.attr("file") = e.file();
            error.attr("line") = e.line();
            error.attr("message") = messageOf(e);
            PyErr_SetObject(sceneError.ptr(), error.ptr());
        }
    });

    prism::python::bindScene(m);
    prism::python::bindRenderer(m);
    prism::python::bindWrite(m);
}
