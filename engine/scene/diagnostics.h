#pragma once
// How the readers report problems. Errors in the line being parsed are thrown as LineError
// (message only); the reader that knows the file and line number turns them into
// prism::FileError ("FILE:LINE: message"). Warnings are Scene::warnings lines.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace prism {

class LineError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws LineError when a scene would hold `count` triangles, more than `limit`.
inline void checkTriangleLimit(uint64_t count, uint64_t limit) {
    if (count > limit)
        throw LineError("the scene would hold more than " + std::to_string(limit) +
                        " triangles, the limit (SceneLimits::maxTriangles)");
}

// Throws LineError when a scene would hold `count` instances (`place` lines), more than `limit`.
inline void checkInstanceLimit(uint64_t count, uint64_t limit) {
    if (count > limit)
        throw LineError("the scene would hold more than " + std::to_string(limit) +
                        " instances, the limit (SceneLimits::maxInstances)");
}

inline std::string warningAt(const std::string &file, int line, const std::string &message) {
    return file + ":" + std::to_string(line) + ": warning: " + message;
}

} // namespace prism
