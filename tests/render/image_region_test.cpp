// Regions of the image (render/image_region.h): a region's render is the whole render's pixels
// there, bit for bit (colour, depth, normal), whatever its place against the 8x8 tiles, on the
// ordinary and the resumable tracer; and the splits that farm tasks take cover the image once.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu_fixture.h"
#include "render/image_region.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"

namespace prism::test {
namespace {

class ImageRegion : public GpuTest {};

// `channels` floats a pixel of a whole image, cut to `r`.
std::vector<float> cut(const std::vector<float> &whole, uint32_t width, uint32_t channels,
                       const PixelRect &r) {
    std::vector<float> out;
    for (uint32_t y = r.y0; y < r.y1; ++y)
        out.insert(out.end(), whole.begin() + (size_t(y) * width + r.x0) * channels,
                   whole.begin() + (size_t(y) * width + r.x1) * channels);
    return out;
}

// The showcase has all three kinds of tile (full, planes only, background), soft shadows
// (samples jittered by pixel) and mirrors; 52x37 leaves part tiles on the right and bottom.
TEST_F(ImageRegion, ARegionIsTheWholeRenderThereBitForBit) {
    Scene scene = loadScene(std::string(PRISM_SCENES_DIR) + "/showcase.scene");
    const uint32_t w = 52, h = 37, spp = 2;
    for (bool resumable : {false, true}) {
        SCOPED_TRACE(resumable ? "resumable" : "one dispatch a sample");
        TracerOptions options;
        options.writeAov = true;
        options.resumable = resumable;
        GpuRender whole = renderGpu(context(), scene, w, h, spp, 3, {}, options);
        ASSERT_EQ(whole.image.x0 + whole.image.y0, 0u);
        ASSERT_EQ(whole.image.fullWidth, w);
        for (PixelRect r : {PixelRect{5, 3, 21, 19}, PixelRect{48, 32, 52, 37},
                            PixelRect{8, 8, 16, 16}, PixelRect{51, 36, 52, 37},
                            PixelRect{0, 0, 52, 37}, PixelRect{17, 0, 18, 37}}) {
            SCOPED_TRACE(regionText(r));
            options.region = r;
            GpuRender part = renderGpu(context(), scene, w, h, spp, 3, {}, options);
            EXPECT_EQ(part.image.width, r.width());
            EXPECT_EQ(part.image.height, r.height());
            EXPECT_EQ(part.image.x0, r.x0);
            EXPECT_EQ(part.image.y0, r.y0);
            EXPECT_EQ(part.image.fullWidth, w);
            EXPECT_EQ(part.image.fullHeight, h);
            EXPECT_EQ(part.image.rgba, cut(whole.image.rgba, w, 4, r));
            EXPECT_EQ(part.image.depth, cut(whole.image.depth, w, 1, r));
            EXPECT_EQ(part.image.normal, cut(whole.image.normal, w, 3, r));
            // Only the tiles round the region are traced: their pixels' camera rays.
            TileRect t = tilesCovering(r.x0, r.y0, r.x1, r.y1);
            uint64_t pixels = uint64_t(std::min(t.x1 * 8, w) - t.x0 * 8) *
                              (std::min(t.y1 * 8, h) - t.y0 * 8);
            EXPECT_EQ(part.frame.rays.primary, pixels * spp);
            EXPECT_EQ(part.frame.tiles[0] + part.frame.tiles[1] + part.frame.tiles[2],
                      t.width() * t.height());
        }
    }
}

TEST_F(ImageRegion, BoundsOutsideTheImageAreRefused) {
    Scene scene = loadScene(std::string(PRISM_SCENES_DIR) + "/showcase.scene");
    TracerOptions options;
    options.region = {0, 0, 33, 8};
    EXPECT_THROW(renderGpu(context(), scene, 32, 24, 1, 1, {}, options), Error);
}

TEST(ImageRegionSplit, TilesCoverTheImageOnceOnBlockEdges) {
    struct Case {
        uint32_t width, height, count;
    };
    for (Case c : {Case{64, 48, 16}, Case{52, 37, 16}, Case{1024, 768, 7}, Case{100, 10, 6},
                   Case{8, 8, 1}, Case{1920, 1080, 240}}) {
        SCOPED_TRACE(std::to_string(c.width) + "x" + std::to_string(c.height) + " / " +
                     std::to_string(c.count));
        std::vector<int> covered(size_t(c.width) * c.height, 0);
        for (uint32_t i = 0; i < c.count; ++i) {
            PixelRect r = splitTile(c.width, c.height, i, c.count);
            ASSERT_FALSE(r.empty());
            EXPECT_EQ(r.x0 % 8, 0u);
            EXPECT_EQ(r.y0 % 8, 0u);
            EXPECT_TRUE(r.x1 % 8 == 0 || r.x1 == c.width);
            EXPECT_TRUE(r.y1 % 8 == 0 || r.y1 == c.height);
            for (uint32_t y = r.y0; y < r.y1; ++y)
                for (uint32_t x = r.x0; x < r.x1; ++x)
                    covered[size_t(y) * c.width + x] += 1;
        }
        EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), std::ptrdiff_t(covered.size()));
    }
    uint32_t columns = 0, rows = 0;
    splitShape(1024, 768, 16, columns, rows);
    EXPECT_EQ(columns * 10 + rows, 44u) << "4 x 4 tiles of 256x192";
    splitShape(1024, 256, 16, columns, rows);
    EXPECT_EQ(columns * 10 + rows, 82u) << "8 x 2 tiles of 128x128";
    splitShape(1024, 768, 7, columns, rows);
    EXPECT_EQ(columns * 10 + rows, 71u) << "a prime: strips across the long side";
    // Tile 5 of 16 on 64x48: column 1, row 1 of 4 x 4.
    EXPECT_EQ(splitTile(64, 48, 5, 16), (PixelRect{16, 8, 32, 24}));
}

TEST(ImageRegionSplit, BadSplitsNameWhatIsWrong) {
    auto message = [](auto f) -> std::string {
        try {
            f();
        } catch (const Error &e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_EQ(message([] { splitTile(64, 48, 16, 16); }),
              "tile 16 is out of range: 16 tiles are numbered 0-15");
    EXPECT_EQ(message([] { splitTile(64, 48, 0, 0); }), "--tile needs at least 1 tile");
    EXPECT_NE(message([] { splitTile(16, 16, 0, 5); }).find("5 tiles cannot split a 16x16 image"),
              std::string::npos);
    EXPECT_NE(message([] { cropWindowPixels(64, 48, -0.1, 0.5, 0, 1); }).find("[0, 1]"),
              std::string::npos);
    EXPECT_NE(message([] { cropWindowPixels(64, 48, 0.5, 0.5, 0, 1); }).find("x0 < x1"),
              std::string::npos);
    EXPECT_NE(message([] { cropWindowPixels(64, 48, 0.51, 0.515, 0, 1); }).find("holds no pixel"),
              std::string::npos);
    EXPECT_NE(message([] { checkPixelBounds({0, 0, 65, 8}, 64, 48); }).find("reach past"),
              std::string::npos);
    EXPECT_NE(message([] { checkPixelBounds({4, 0, 4, 8}, 64, 48); }).find("x0 < x1"),
              std::string::npos);
}

// pbrt's crop window: pixels from ceil(W * x0) to ceil(W * x1), so that windows sharing an
// edge share no pixel and leave none out.
TEST(ImageRegionSplit, CropWindowsAsPbrtRoundsThem) {
    EXPECT_EQ(cropWindowPixels(100, 50, 0.0, 0.333, 0.0, 1.0), (PixelRect{0, 0, 34, 50}));
    EXPECT_EQ(cropWindowPixels(100, 50, 0.333, 0.667, 0.5, 1.0), (PixelRect{34, 25, 67, 50}));
    EXPECT_EQ(cropWindowPixels(100, 50, 0.667, 1.0, 0.0, 0.5), (PixelRect{67, 0, 100, 25}));
}

} // namespace
} // namespace prism::test
