#pragma once
// What the binding files share: the Python-side objects and the registration functions
// module.cpp calls. Bindings only: the work is the engine's (session/, render/).
#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "scene/scene.h"
#include "session/prepared_scene.h"

namespace prism::python {

// prism.Scene: a loaded scene, prepared once (centred, its grid built), and the camera the next
// render uses, kept in the prepared scene's coordinates so that a frame set from Python is the
// camera prism-render --frames uses, to the bit.
struct PyScene {
    // Replaced, never changed, when a frame moves keyed instances: a renderer may be tracing
    // the scene as it was.
    std::shared_ptr<const PreparedScene> prepared;
    // One per load, kept by the moved copies: a renderer that traced this scene at another
    // frame uploads the moved arrays to the tracer it has (RayTracer::setScene), no new compile.
    uint64_t lineage = 0;
    Camera camera; // in prepared->scene's (centred) coordinates
    double frame = 1.0;
    std::string path; // the .scene file, or "<string>" (last_stats' "scene")
    double loadMs = 0.0; // reading the file (last_stats' "load_ms")
};

void bindScene(pybind11::module_ &m);
void bindRenderer(pybind11::module_ &m);
void bindWrite(pybind11::module_ &m);

} // namespace prism::python
