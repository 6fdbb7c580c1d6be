#pragma once
// Reading any image OpenImageIO understands as float pixels, for tests and tools.
#include "io/image_metadata.h"

#include <filesystem>
#include <string>
#include <vector>

namespace prism {

struct LoadedImage {
    int width = 0, height = 0, channels = 0;
    // The data window's place in the display window, and the display window's size (an EXR
    // of a region: render/image_region.h); x = y = 0 and full = width x height otherwise.
    int x = 0, y = 0, fullWidth = 0, fullHeight = 0;
    std::vector<float> pixels; // width*height*channels, interleaved, row 0 = top;
                               // 8-bit files come back as code/255 (no colour conversion)
    std::vector<std::string> channelNames;
    ImageMetadata metadata; // every string, float and int attribute the file carries
};

// Throws prism::Error naming the path and OIIO's error text.
LoadedImage readImage(const std::filesystem::path &path);

} // namespace prism
