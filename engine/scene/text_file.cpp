#include "scene/text_file.h"

#include "core/error.h"
#include "core/huge_pages.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
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

    // A regular file is read in one call into a string sized once: a stream copy
    // (`<< rdbuf()`) grew its buffer step by step and took 330 ms for a 41 MB OBJ file, as long
    // as parsing it (issue 31). A pipe or device has no size and is read as a stream.
    bool sized = std::filesystem::is_regular_file(status);
    std::ifstream in(path, sized ? std::ios::binary | std::ios::ate : std::ios::binary);
    if (!in)
        fail(std::strerror(errno));
    std::string bytes;
    if (!sized) {
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } else if (std::streamoff size = in.tellg(); size > 0) {
        bytes.reserve(size_t(size));
        adviseHugePages(bytes.data(), size_t(size));
        bytes.resize(size_t(size));
        in.seekg(0);
        in.read(bytes.data(), size);
        if (in.gcount() != size)
            fail(in.bad() ? std::strerror(errno) : "it became shorter while being read");
    }
    if (in.bad())
        fail(std::strerror(errno));
    return bytes;
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
