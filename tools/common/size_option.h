#pragma once
// "--size WxH", shared by the tools.
#include <cstdint>
#include <string>

namespace prism {

struct ImageSize {
    uint32_t width = 0, height = 0;
};

// Parses "1024x768" (each side 1..16384). Throws prism::Error naming `option` and the text.
ImageSize parseSizeOption(const std::string &text, const std::string &option = "--size");

} // namespace prism
