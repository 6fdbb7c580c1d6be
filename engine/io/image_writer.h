#pragma once
// Writing rendered images to disk through OpenImageIO, atomically: the file at `path` is
// either the old one or the complete new one, never a partial write.
#include "io/image_metadata.h"

#include <filesystem>
#include <vector>

namespace prism {

struct OutputImage {
    int width = 0, height = 0;
    std::vector<float> rgba;   // width*height*4, linear, row 0 = top
    std::vector<float> depth;  // empty or width*height: EXR channel "Z"
    std::vector<float> normal; // empty or width*height*3: EXR channels "N.X", "N.Y", "N.Z"
};

// By extension (case-insensitive):
//   .exr  float32 R,G,B,A (+ Z, + N.X N.Y N.Z when present), metadata as header attributes;
//   .png  8-bit RGB, sRGB-encoded (clamped, rounded), string metadata as text chunks.
// Anything else, a malformed image or any I/O failure throws prism::Error naming the path.
void writeImage(const std::filesystem::path &path, const OutputImage &image,
                const ImageMetadata &meta);

} // namespace prism
