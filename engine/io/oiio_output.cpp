#include "io/oiio_output.h"

#include "core/error.h"

#include <string>

namespace prism {
namespace {

[[noreturn]] void fail(const std::filesystem::path &reportedPath, const std::string &why) {
    throw Error("cannot write image '" + reportedPath.string() + "': " + why);
}

} // namespace

void writeWithOiio(const std::filesystem::path &path, const char *formatName,
                   const OIIO::ImageSpec &spec, const void *pixels,
                   const std::filesystem::path &reportedPath) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(formatName);
    if (!out)
        fail(reportedPath,
             "OpenImageIO has no '" + std::string(formatName) + "' writer: " + OIIO::geterror());
    if (!out->open(path.string(), spec))
        fail(reportedPath, out->geterror());
    const bool written = out->write_image(spec.format, pixels);
    const bool closed = out->close(); // close even after a failed write: flushes, frees
    if (!written || !closed)
        fail(reportedPath, out->geterror());
}

} // namespace prism
