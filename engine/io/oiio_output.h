#pragma once
// One call that writes a whole image with OpenImageIO, turning its errors into prism::Error.
#include <OpenImageIO/imageio.h>

#include <filesystem>

namespace prism {

// Writes `pixels` (interleaved, spec.format per channel, row 0 = top) to `path` in the
// OIIO format `formatName` ("openexr", "png"). `reportedPath` names the file in errors.
void writeWithOiio(const std::filesystem::path &path, const char *formatName,
                   const OIIO::ImageSpec &spec, const void *pixels,
                   const std::filesystem::path &reportedPath);

} // namespace prism
