// prism.write: an image from NumPy arrays to a file, the way prism-render writes its own (EXR
// float channels with metadata, or sRGB PNG), atomically.
#include <cstring>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "io/image_writer.h"

namespace py = pybind11;

namespace prism::python {
namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// An H x W x C array (C from `channels`), or H x W for one channel; its height and width.
FloatArray checkedArray(const py::object &given, const char *name, std::initializer_list<int> channels,
                        int &height, int &width) {
    FloatArray a = FloatArray::ensure(given);
    if (!a)
        throw py::value_error(std::string(name) + " must be an array of numbers");
    int c = a.ndim() == 2 ? 1 : a.ndim() == 3 ? int(a.shape(2)) : 0;
    bool fits = false;
    for (int wanted : channels)
        fits = fits || c == wanted;
    if (!fits || a.ndim() < 2 || a.shape(0) == 0 || a.shape(1) == 0) {
        std::string shape;
        for (py::ssize_t d = 0; d < a.ndim(); ++d)
            shape += (d ? " x " : "") + std::to_string(a.shape(d));
        throw py::value_error(std::string(name) + " must be height x width x channels with " +
                              (c == 0 ? std::string("channels") : "these channels") +
                              " as documented, got shape " + (shape.empty() ? "()" : shape));
    }
    if (height == 0) {
        height = int(a.shape(0));
        width = int(a.shape(1));
    } else if (int(a.shape(0)) != height || int(a.shape(1)) != width) {
        throw py::value_error(std::string(name) + " is " + std::to_string(a.shape(0)) + " x " +
                              std::to_string(a.shape(1)) + ", the rgb image " +
                              std::to_string(height) + " x " + std::to_string(width));
    }
    return a;
}

ImageMetadata metadataOf(const py::dict &given) {
    ImageMetadata meta;
    for (auto [key, value] : given) {
        std::string name = py::str(key);
        // bool is an int in Python; it is written as one.
        if (py::isinstance<py::int_>(value))
            meta.ints.emplace_back(name, value.cast<int>());
        else if (py::isinstance<py::float_>(value))
            meta.floats.emplace_back(name, value.cast<float>());
        else if (py::isinstance<py::str>(value))
            meta.strings.emplace_back(name, value.cast<std::string>());
        else
            throw py::value_error("metadata '" + name + "': values are str, int or float, got " +
                                  std::string(py::str(py::type::of(value).attr("__name__"))));
    }
    return meta;
}

void write(const std::string &path, const py::object &rgb, const py::object &z,
           const py::object &n, const py::dict &metadata) {
    int height = 0, width = 0;
    FloatArray colour = checkedArray(rgb, "rgb", {3, 4}, height, width);
    OutputImage image;
    image.width = width;
    image.height = height;
    size_t pixels = size_t(width) * size_t(height);
    size_t channels = colour.ndim() == 3 ? size_t(colour.shape(2)) : 1;
    image.rgba.resize(pixels * 4);
    const float *from = colour.data();
    for (size_t i = 0; i < pixels; ++i) {
        std::memcpy(&image.rgba[4 * i], from + channels * i, 3 * sizeof(float));
        image.rgba[4 * i + 3] = channels == 4 ? from[channels * i + 3] : 1.0f;
    }
    if (!z.is_none()) {
        FloatArray depth = checkedArray(z, "z", {1}, height, width);
        image.depth.assign(depth.data(), depth.data() + pixels);
    }
    if (!n.is_none()) {
        FloatArray normal = checkedArray(n, "n", {3}, height, width);
        image.normal.assign(normal.data(), normal.data() + pixels * 3);
    }
    ImageMetadata meta = metadataOf(metadata);
    py::gil_scoped_release released; // compressing a big EXR takes a while
    writeImage(path, image, meta);
}

} // namespace

void bindWrite(py::module_ &m) {
    m.def("write", &write, py::arg("path"), py::arg("rgb"), py::arg("z") = py::none(),
          py::arg("n") = py::none(), py::arg("metadata") = py::dict(),
          "Writes an image as prism-render does, whole or not at all (a temporary file, then "
          "renamed): .exr keeps float R, G, B, A (A from a 4th channel, else 1), with z "
          "(H x W x 1 or H x W) as channel Z and n (H x W x 3) as N.X, N.Y, N.Z, and metadata "
          "(str: str, int or float) as header attributes; .png is 8-bit sRGB, clamped, with "
          "string metadata as text. Raises ValueError for arrays of the wrong shape, "
          "RuntimeError for an unwritable path or extension.");
}

} // namespace prism::python
