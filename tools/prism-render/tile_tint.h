#pragma once
// --show-tiles: the rendered image with each 8x8 tile tinted by the tracer that ran it
// (render/traced_tiles.h), to see what tile culling leaves to the cheaper tracers.
#include <cstdint>
#include <vector>

#include "render/image_region.h"

namespace prism {

// Full tiles stay as rendered; tiles traced without the grid (planes only) are tinted blue,
// background tiles grey. rgba: the pixels of `part` of `image` (a region's render, or all of
// it), RGBA floats, row 0 at the top; classes: one per tile of `image`, row by row
// (RayTracer::lastTileClasses). Does nothing when classes is empty.
void tintTilesByClass(std::vector<float> &rgba, const PixelRect &image, const PixelRect &part,
                      const std::vector<uint8_t> &classes);

} // namespace prism
