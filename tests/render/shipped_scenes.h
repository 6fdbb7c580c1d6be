#pragma once
// The names of the shipped scenes (assets/scenes/*.scene, not the study scenes below it), for
// tests that run on every one.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace prism::test {

inline std::vector<std::string> shippedScenes() {
    std::vector<std::string> names;
    for (const auto &entry : std::filesystem::directory_iterator(PRISM_SCENES_DIR))
        if (entry.path().extension() == ".scene")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace prism::test
