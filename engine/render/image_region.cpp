#include "render/image_region.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"

namespace prism {
namespace {

constexpr uint32_t kBlock = 8; // the tracer's 8x8 workgroups (render/traced_tiles.h, kTileSize)

uint32_t blocks(uint32_t pixels) {
    return (pixels + kBlock - 1) / kBlock;
}

// Edge k of `parts` equal runs of `blockCount` blocks, in pixels, the last at `pixels`.
uint32_t splitEdge(uint32_t pixels, uint32_t blockCount, uint32_t parts, uint32_t k) {
    if (k == parts)
        return pixels;
    return uint32_t(uint64_t(blockCount) * k / parts) * kBlock;
}

std::string fraction(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

} // namespace

PixelRect cropWindowPixels(uint32_t width, uint32_t height, double x0, double x1, double y0,
                           double y1) {
    for (double v : {x0, x1, y0, y1})
        if (!(v >= 0.0 && v <= 1.0))
            throw Error("--crop fractions must lie in [0, 1], got " + fraction(v));
    if (!(x0 < x1) || !(y0 < y1))
        throw Error("--crop needs x0 < x1 and y0 < y1 (X0,X1,Y0,Y1), got " + fraction(x0) + "," +
                    fraction(x1) + "," + fraction(y0) + "," + fraction(y1));
    PixelRect r{uint32_t(std::ceil(width * x0)), uint32_t(std::ceil(height * y0)),
                uint32_t(std::ceil(width * x1)), uint32_t(std::ceil(height * y1))};
    if (r.empty())
        throw Error("--crop " + fraction(x0) + "," + fraction(x1) + "," + fraction(y0) + "," +
                    fraction(y1) + " holds no pixel of a " + std::to_string(width) + "x" +
                    std::to_string(height) + " image");
    return r;
}

void checkPixelBounds(const PixelRect &b, uint32_t width, uint32_t height) {
    if (b.x0 >= b.x1 || b.y0 >= b.y1)
        throw Error("--pixel-bounds needs x0 < x1 and y0 < y1 (X0,X1,Y0,Y1), got " +
                    regionText(b));
    if (b.x1 > width || b.y1 > height)
        throw Error("--pixel-bounds " + regionText(b) + " reach past the " +
                    std::to_string(width) + "x" + std::to_string(height) + " image");
}

void splitShape(uint32_t width, uint32_t height, uint32_t count, uint32_t &columns,
                uint32_t &rows) {
    uint32_t bx = blocks(width), by = blocks(height);
    if (count == 0)
        throw Error("--tile needs at least 1 tile");
    double best = std::numeric_limits<double>::infinity();
    columns = rows = 0;
    for (uint32_t c = 1; c <= count; ++c) {
        if (count % c != 0 || c > bx || count / c > by)
            continue;
        uint32_t r = count / c;
        // How far from square a tile is, either way.
        double skew = std::abs(std::log((double(width) / c) / (double(height) / r)));
        if (skew < best) {
            best = skew;
            columns = c;
            rows = r;
        }
    }
    if (columns == 0)
        throw Error(std::to_string(count) + " tiles cannot split a " + std::to_string(width) +
                    "x" + std::to_string(height) + " image: no columns x rows of 8x8 blocks (" +
                    std::to_string(bx) + " x " + std::to_string(by) + ") make " +
                    std::to_string(count));
}

PixelRect splitTile(uint32_t width, uint32_t height, uint32_t index, uint32_t count) {
    if (count > 0 && index >= count)
        throw Error("tile " + std::to_string(index) + " is out of range: " +
                    std::to_string(count) + " tiles are numbered 0-" + std::to_string(count - 1));
    uint32_t columns = 0, rows = 0;
    splitShape(width, height, count, columns, rows);
    uint32_t bx = blocks(width), by = blocks(height);
    uint32_t cx = index % columns, cy = index / columns;
    return {splitEdge(width, bx, columns, cx), splitEdge(height, by, rows, cy),
            splitEdge(width, bx, columns, cx + 1), splitEdge(height, by, rows, cy + 1)};
}

std::string regionText(const PixelRect &r) {
    return std::to_string(r.x0) + "," + std::to_string(r.x1) + "," + std::to_string(r.y0) + "," +
           std::to_string(r.y1);
}

} // namespace prism
