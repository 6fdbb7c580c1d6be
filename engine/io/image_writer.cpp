#include "io/image_writer.h"

#include "core/error.h"
#include "io/format_writers.h"
#include "io/staged_file.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>

namespace prism {
namespace {

std::string lowerExtension(const std::filesystem::path &path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

[[noreturn]] void fail(const std::filesystem::path &path, const std::string &why) {
    throw Error("cannot write image '" + path.string() + "': " + why);
}

void checkShape(const std::filesystem::path &path, const OutputImage &image) {
    if (image.width <= 0 || image.height <= 0)
        fail(path, "size " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                       " is empty");
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    auto checkSize = [&](const char *what, std::size_t actual, std::size_t perPixel) {
        if (actual != pixels * perPixel)
            fail(path, std::string(what) + " has " + std::to_string(actual) + " values, expected " +
                           std::to_string(pixels * perPixel));
    };
    if (image.fullWidth > 0 &&
        (image.x < 0 || image.y < 0 || image.x + image.width > image.fullWidth ||
         image.y + image.height > image.fullHeight))
        fail(path, "the part at " + std::to_string(image.x) + "," + std::to_string(image.y) +
                       " reaches past the whole " + std::to_string(image.fullWidth) + "x" +
                       std::to_string(image.fullHeight) + " image");
    checkSize("rgba", image.rgba.size(), 4);
    if (!image.depth.empty())
        checkSize("depth", image.depth.size(), 1);
    if (!image.normal.empty())
        checkSize("normal", image.normal.size(), 3);
}

// Checked up front so the message names the real cause, not the temporary file.
void checkDirectory(const std::filesystem::path &path) {
    const std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        fail(path, "directory '" + dir.string() + "' does not exist");
}

} // namespace

void writeImage(const std::filesystem::path &path, const OutputImage &image,
                const ImageMetadata &meta) {
    const std::string ext = lowerExtension(path);
    if (ext != ".exr" && ext != ".png")
        fail(path, (ext.empty() ? std::string("no extension")
                                : "unsupported extension '" + path.extension().string() + "'") +
                       " (supported: .exr, .png)");
    checkShape(path, image);
    const std::string &c = image.exrCompression;
    if (c != "zip:1" && c != "zips:1" && c != "piz" && c != "rle" && c != "none")
        fail(path, "EXR compression '" + c + "' is not one of the lossless zip:1, zips:1, piz, "
                   "rle, none");
    checkDirectory(path);

    StagedFile staged(path); // removes the temporary file on any throw below
    if (ext == ".exr")
        writeExr(staged.tempPath(), image, meta, path);
    else
        writePng(staged.tempPath(), image, meta, path);
    staged.commit();
}

void preloadImageFiles() {} // OpenImageIO was loaded with the program

} // namespace prism
