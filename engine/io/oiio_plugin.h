#pragma once
// Everything of Prism that calls OpenImageIO, as a table of functions that a shared library
// (libprism_oiio.so, io/oiio_plugin.cpp) hands out. OpenImageIO brings about 260 shared
// libraries that take 0.4-1 s to map and relocate; a front end that may never read or write an
// image file (the Python module: `import prism` and renders of untextured scenes) links
// prism_oiio_late instead of prism_oiio and loads the library at its first call
// (io/late_oiio.cpp). So do prism-render, which loads it on a thread of its own while the
// scene loads (preloadImageFiles), prism-merge and prism-view; prism-bench and prism-gridbench
// link prism_oiio and call it directly.
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/image_reader.h"
#include "io/image_writer.h"
#include "scene/texture_loader.h"

namespace prism {

// Raised whenever a function's signature or meaning changes: a library of another build is
// refused instead of called wrongly.
constexpr uint32_t kOiioPluginVersion = 2; // 2: OutputImage::exrCompression

struct OiioPluginTable {
    uint32_t version;
    // Each returns "" on success, else the message of what it threw: no exception crosses the
    // library's edge (each side has its own copy of prism::Error's type).
    std::string (*readTexture)(const std::filesystem::path &path, TexelMeaning meaning,
                               Texture &out);
    std::string (*writeImage)(const std::filesystem::path &path, const OutputImage &image,
                              const ImageMetadata &meta);
    std::string (*readImage)(const std::filesystem::path &path, LoadedImage &out);
};

} // namespace prism

// The library's one exported symbol.
extern "C" const prism::OiioPluginTable *prism_oiio_plugin_table();
constexpr const char *kOiioPluginFile = "libprism_oiio.so";
