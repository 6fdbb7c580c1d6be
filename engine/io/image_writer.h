#pragma once
// Writing rendered images to disk through OpenImageIO, atomically: the file at `path` is
// either the old one or the complete new one, never a partial write.
#include "io/image_metadata.h"

#include <filesystem>
#include <string>
#include <vector>

namespace prism {

struct OutputImage {
    int width = 0, height = 0;
    // A part of a larger image (a region's render): where it starts in that image, and the
    // image's size (0: this image is whole). EXR keeps them as the data window inside the
    // display window; PNG has no such thing and holds the part alone.
    int x = 0, y = 0;
    int fullWidth = 0, fullHeight = 0;
    std::vector<float> rgba;   // width*height*4, linear, row 0 = top
    std::vector<float> depth;  // empty or width*height: EXR channel "Z"
    std::vector<float> normal; // empty or width*height*3: EXR channels "N.X", "N.Y", "N.Z"
    // EXR only: OpenEXR's compression as OpenImageIO names it, one of the lossless ones
    // ("zip:1", "zips:1", "piz", "rle", "none"), so that floats come back bit for bit.
    std::string exrCompression = "zip:1";
};

// By extension (case-insensitive):
//   .exr  float32 R,G,B,A (+ Z, + N.X N.Y N.Z when present), metadata as header attributes,
//         a part's place as its data window;
//   .png  8-bit RGB, sRGB-encoded (clamped, rounded), string metadata as text chunks.
// Anything else, a malformed image or any I/O failure throws prism::Error naming the path.
void writeImage(const std::filesystem::path &path, const OutputImage &image,
                const ImageMetadata &meta);

// Where image files go through OpenImageIO loaded at the first call (io/oiio_plugin.h), loads
// it now, so that a caller can have that done on a thread of its own while other work goes on;
// failures are left for the first real call to report. Linked directly, it does nothing.
void preloadImageFiles();

} // namespace prism
