#pragma once
// How the readers report problems. Errors in the line being parsed are thrown as LineError
// (message only); the reader that knows the file and line number turns them into
// prism::FileError ("FILE:LINE: message"). Warnings are Scene::warnings lines.
#include <stdexcept>
#include <string>

namespace prism {

class LineError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline std::string warningAt(const std::string &file, int line, const std::string &message) {
    return file + ":" + std::to_string(line) + ": warning: " + message;
}

} // namespace prism
