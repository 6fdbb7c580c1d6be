#pragma once
// A whole file as bytes, for comparing outputs byte for byte.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace prism::test {

// Throws when the file cannot be opened, so a missing file reads as that, not as empty.
inline std::string readFile(const std::filesystem::path &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read " + path.string());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace prism::test
