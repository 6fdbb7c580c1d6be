#pragma once
// A scene's warnings as one text, one per line: the message of a failed "no warnings" check.
#include <string>

#include "scene/scene.h"

namespace prism::test {

inline std::string allWarnings(const Scene &scene) {
    std::string text;
    for (const std::string &w : scene.warnings)
        text += w + "\n";
    return text;
}

} // namespace prism::test
