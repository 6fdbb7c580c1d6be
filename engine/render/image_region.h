#pragma once
// A part of the image to render (issue 32: a still split across the machines of a farm). The
// camera still sees the whole image, and every pixel is traced exactly as in a whole render
// (its rays and samples depend on its place in the whole image alone), so tiles rendered apart
// and put together are the whole image, bit for bit.
#include <cstdint>
#include <string>

namespace prism {

// Pixels [x0, x1) x [y0, y1) of the image, row 0 at the top.
struct PixelRect {
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    uint32_t width() const { return x1 > x0 ? x1 - x0 : 0; }
    uint32_t height() const { return y1 > y0 ? y1 - y0 : 0; }
    bool empty() const { return width() == 0 || height() == 0; }
    bool operator==(const PixelRect &) const = default;
};

inline PixelRect wholeImage(uint32_t width, uint32_t height) {
    return {0, 0, width, height};
}

// pbrt's --cropwindow: fractions x0 < x1, y0 < y1 of [0, 1], the pixels from ceil(W * x0) to
// ceil(W * x1) (and likewise in y), so that crop windows that share an edge share no pixel and
// miss none. Throws prism::Error for fractions outside [0, 1], not increasing, or a window with
// no pixel in it.
PixelRect cropWindowPixels(uint32_t width, uint32_t height, double x0, double x1, double y0,
                           double y1);

// Checks pixel bounds against the image; throws prism::Error naming what is wrong.
void checkPixelBounds(const PixelRect &bounds, uint32_t width, uint32_t height);

// Tile `index` (0 .. count - 1, row by row from the top left) of the image split into `count`
// tiles of as nearly equal size as 8x8 blocks allow (the tracer's workgroups: an edge on a
// block's edge traces no pixel twice). The split's columns x rows multiply to `count`, and of
// those the one whose tiles are the most nearly square. Throws prism::Error for an index out of
// range, or more tiles than the image has blocks.
PixelRect splitTile(uint32_t width, uint32_t height, uint32_t index, uint32_t count);
// The columns and rows splitTile uses for `count` tiles.
void splitShape(uint32_t width, uint32_t height, uint32_t count, uint32_t &columns,
                uint32_t &rows);

// "x0,x1,y0,y1", as the options take it.
std::string regionText(const PixelRect &rect);

} // namespace prism
