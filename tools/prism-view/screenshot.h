#pragma once
// F12: the accumulated radiance as an EXR (linear float) and a PNG (sRGB), both carrying the
// metadata prism-render writes.
#include <filesystem>

#include "render/ray_tracer.h"
#include "render_metadata.h"

namespace prism {

// "prism-view-<scene>-<YYYYmmdd-HHMMSS>" in the current directory.
std::filesystem::path defaultScreenshotBase(const std::filesystem::path &scenePath);

// Writes base.exr and base.png (any extension of `base` is replaced); returns the EXR's path.
std::filesystem::path writeScreenshot(const std::filesystem::path &base, TracedImage image,
                                      const RenderRecord &record);

} // namespace prism
