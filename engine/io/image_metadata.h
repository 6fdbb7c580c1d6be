#pragma once
// Named values stored with an image: EXR header attributes, PNG text chunks (strings only).
// Prism's own names use the "prism:" prefix, e.g. "prism:renderTimeMs"; OIIO writes any
// prefix that is not an image format's name into EXR verbatim.
#include <string>
#include <utility>
#include <vector>

namespace prism {

struct ImageMetadata {
    std::vector<std::pair<std::string, std::string>> strings;
    std::vector<std::pair<std::string, float>> floats;
    std::vector<std::pair<std::string, int>> ints;
};

} // namespace prism
