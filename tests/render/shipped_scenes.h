#pragma once
// The names of the shipped scenes (assets/scenes/*.scene, not the study scenes below it), for
// tests that run on every one.
#include <algorithm>
#include <cctype>
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

// A scene's name as a test name: gtest takes only letters, digits and '_' (bump-maps ->
// bump_maps).
inline std::string testNameOf(std::string scene) {
    for (char &c : scene)
        if (!std::isalnum(static_cast<unsigned char>(c)))
            c = '_';
    return scene;
}

} // namespace prism::test
