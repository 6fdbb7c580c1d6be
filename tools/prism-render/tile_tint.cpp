#include "tile_tint.h"

#include "core/error.h"
#include "render/traced_tiles.h"

namespace prism {

void tintTilesByClass(std::vector<float> &rgba, const PixelRect &image, const PixelRect &part,
                      const std::vector<uint8_t> &classes) {
    if (classes.empty())
        return;
    TileRect tiles = imageTiles(image.width(), image.height());
    if (classes.size() != size_t(tiles.width()) * tiles.height())
        throw Error("tile classes do not match the image's tiles");
    const float planes[3] = {0.1f, 0.35f, 1.0f}, background[3] = {0.5f, 0.5f, 0.5f};
    for (uint32_t y = part.y0; y < part.y1; ++y)
        for (uint32_t x = part.x0; x < part.x1; ++x) {
            uint8_t c = classes[size_t(y / kTileSize) * tiles.width() + x / kTileSize];
            if (c == kTileFull)
                continue;
            const float *tint = c == kTilePlanesOnly ? planes : background;
            float *pixel = &rgba[(size_t(y - part.y0) * part.width() + (x - part.x0)) * 4];
            for (int k = 0; k < 3; ++k) // half the tint: the image stays readable through it
                pixel[k] = 0.5f * pixel[k] + 0.5f * tint[k];
        }
}

} // namespace prism
