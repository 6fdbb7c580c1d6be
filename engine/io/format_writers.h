#pragma once
// One writer per supported file format. Each writes `file` directly (the caller stages it)
// and names `reportedPath` in its errors. The image is already validated.
#include "io/image_writer.h"

#include <filesystem>

namespace prism {

void writeExr(const std::filesystem::path &file, const OutputImage &image,
              const ImageMetadata &meta, const std::filesystem::path &reportedPath);

void writePng(const std::filesystem::path &file, const OutputImage &image,
              const ImageMetadata &meta, const std::filesystem::path &reportedPath);

} // namespace prism
