#pragma once
// --show-tiles: the rendered image with each 8x8 tile tinted by the tracer that ran it
// (render/traced_tiles.h), to see what tile culling leaves to the cheaper tracers.
#include <cstdint>
#include <vector>

namespace prism {

// Full tiles stay as rendered; tiles traced without the grid (planes only) are tinted blue,
// background tiles grey. rgba: width x height RGBA floats, row 0 at the top; classes: one per
// tile, row by row (RayTracer::lastTileClasses). Does nothing when classes is empty.
void tintTilesByClass(std::vector<float> &rgba, uint32_t width, uint32_t height,
                      const std::vector<uint8_t> &classes);

} // namespace prism
