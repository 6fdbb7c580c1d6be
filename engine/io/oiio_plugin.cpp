// libprism_oiio.so: prism_oiio's functions behind the table of io/oiio_plugin.h.
#include "io/oiio_plugin.h"

#include <exception>

namespace prism {
namespace {

template <typename Call>
std::string caught(Call call) {
    try {
        call();
        return "";
    } catch (const std::exception &e) {
        std::string what = e.what();
        return what.empty() ? "unknown error" : what;
    } catch (...) {
        return "unknown error";
    }
}

const OiioPluginTable kTable{
    kOiioPluginVersion,
    [](const std::filesystem::path &path, TexelMeaning meaning, Texture &out) {
        return caught([&] { out = readTexture(path, meaning); });
    },
    [](const std::filesystem::path &path, const OutputImage &image, const ImageMetadata &meta) {
        return caught([&] { writeImage(path, image, meta); });
    },
    [](const std::filesystem::path &path, LoadedImage &out) {
        return caught([&] { out = readImage(path); });
    }};

} // namespace
} // namespace prism

extern "C" __attribute__((visibility("default"))) const prism::OiioPluginTable *
prism_oiio_plugin_table() {
    return &prism::kTable;
}
