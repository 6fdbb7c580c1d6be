#include "scene/text_file.h"

#include "core/error.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

namespace prism {
namespace {

[[noreturn]] void failRead(const std::filesystem::path &path, const char *what,
                           const std::string &why) {
    throw Error(std::string("cannot read ") + what + " '" + displayPath(path) + "': " + why);
}

} // namespace

std::string readTextFile(const std::filesystem::path &path, const char *what) {
    auto fail = [&](const std::string &why) { failRead(path, what, why); };
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        fail(ec ? ec.message() : "no such file");
    if (std::filesystem::is_directory(status))
        fail("it is a directory");

    std::ifstream in(path, std::ios::binary);
    if (!in)
        fail(std::strerror(errno));
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad())
        fail(std::strerror(errno));
    return std::move(bytes).str();
}

std::string displayPath(const std::filesystem::path &path) {
    return path.lexically_normal().generic_string();
}

std::filesystem::path resolveInputPath(const std::filesystem::path &baseDir, std::string written) {
    std::replace(written.begin(), written.end(), '\\', '/');
    std::filesystem::path path(written);
    return path.is_absolute() ? path : baseDir / path;
}

} // namespace prism
