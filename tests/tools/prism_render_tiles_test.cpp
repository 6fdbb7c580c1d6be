// Regions and tiles (issue 32): prism-render --crop, --pixel-bounds and --tile I/N write a part
// of the image as an EXR whose data window is the part's place; prism-merge (or oiiotool, the
// recipe docs/farm.md gives) puts 16 tiles together into the image one process renders, bit
// for bit; bad regions and bad tile sets are refused with no output.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "io/image_reader.h"
#include "temp_dir_fixture.h"

namespace fs = std::filesystem;

namespace {

using prism::test::CliResult;

class PrismRenderTiles : public prism::test::TempDirTest {
protected:
    // The showcase at 64x48 with 2 samples (jittered pixels, soft shadows) and both AOVs:
    // every channel of a tile must match.
    CliResult render(const std::string &args) {
        return prism::test::runTool(PRISM_RENDER_EXE,
                                    std::string(PRISM_SCENES_DIR) + "/showcase.scene --size 64x48 "
                                    "--spp 2 --depth 3 --aov z,normal --quiet " + args);
    }
    CliResult merge(const std::string &args) {
        return prism::test::runTool(PRISM_MERGE_EXE, args);
    }
    std::string path(const std::string &name) const { return (dir() / name).string(); }
    std::string tiles(int count) const {
        std::string list;
        for (int i = 0; i < count; ++i) {
            list += ' ';
            list += path("tile" + std::to_string(i) + ".exr");
        }
        return list;
    }
    void renderTiles(int count, const std::string &args = "") {
        for (int i = 0; i < count; ++i) {
            CliResult r = render("--tile " + std::to_string(i) + "/" + std::to_string(count) +
                                 " -o " + path("tile{tile}.exr") + args);
            ASSERT_EQ(r.exitCode, 0) << r.out;
        }
    }
};

// The pixels of `whole` (all its channels) inside a part's data window.
std::vector<float> cut(const prism::LoadedImage &whole, const prism::LoadedImage &part) {
    std::vector<float> out;
    size_t c = size_t(whole.channels);
    for (int y = part.y; y < part.y + part.height; ++y)
        out.insert(out.end(), whole.pixels.begin() + (size_t(y) * whole.width + part.x) * c,
                   whole.pixels.begin() + (size_t(y) * whole.width + part.x + part.width) * c);
    return out;
}

TEST_F(PrismRenderTiles, SixteenTilesMergeIntoTheWholeImageBitForBit) {
    ASSERT_EQ(render("-o " + path("whole.exr")).exitCode, 0);
    renderTiles(16);
    prism::LoadedImage whole = prism::readImage(dir() / "whole.exr");
    prism::LoadedImage five = prism::readImage(dir() / "tile5.exr");
    // 4 x 4 tiles on 8-pixel edges: columns of 16, and the 6 rows of blocks split 1, 2, 1, 2.
    EXPECT_EQ(five.width * 100 + five.height, 16 * 100 + 16);
    EXPECT_EQ(five.x * 100 + five.y, 16 * 100 + 8) << "column 1, row 1";
    EXPECT_EQ(five.fullWidth * 100 + five.fullHeight, 64 * 100 + 48);
    EXPECT_EQ(five.pixels, cut(whole, five));
    EXPECT_EQ(five.channelNames, whole.channelNames);

    CliResult merged = merge(tiles(16) + " -o " + path("merged.exr"));
    ASSERT_EQ(merged.exitCode, 0) << merged.out;
    EXPECT_NE(merged.out.find("16 tiles"), std::string::npos) << merged.out;
    prism::LoadedImage m = prism::readImage(dir() / "merged.exr");
    EXPECT_EQ(m.width * 100 + m.height, 64 * 100 + 48);
    EXPECT_EQ(m.x + m.y, 0);
    EXPECT_EQ(m.channelNames, whole.channelNames);
    EXPECT_EQ(m.pixels, whole.pixels) << "merged tiles are the one-process render";
    // The tiles' rays add up to the whole render's; what only a tile says is gone.
    auto metaString = [](const prism::LoadedImage &image, const std::string &name) {
        for (const auto &[key, value] : image.metadata.strings)
            if (key == name)
                return value;
        return std::string("(none)");
    };
    EXPECT_EQ(metaString(m, "prism:raysPrimary"), metaString(whole, "prism:raysPrimary"));
    EXPECT_EQ(metaString(m, "prism:raysShadow"), metaString(whole, "prism:raysShadow"));
    EXPECT_EQ(metaString(m, "prism:region"), "(none)");
    EXPECT_EQ(metaString(m, "prism:tile"), "(none)");
    EXPECT_EQ(metaString(five, "prism:region"), "16,32,8,24");
    EXPECT_EQ(metaString(five, "prism:tile"), "5/16");

    // The oiiotool recipe of docs/farm.md: each tile over the others (alpha 1 inside a tile's
    // data window, nothing outside it), flattened to the display window.
    std::string over = tiles(1);
    for (int i = 1; i < 16; ++i) {
        over += ' ';
        over += path("tile" + std::to_string(i) + ".exr");
        over += " --over";
    }
    CliResult oiio = prism::test::runTool("oiiotool", over + " --fullpixels -o " +
                                                          path("oiio.exr"));
    ASSERT_EQ(oiio.exitCode, 0) << "oiiotool (Debian's openimageio-tools, installed by "
                                   "tools/scripts/install-deps.sh) failed: "
                                << oiio.out;
    EXPECT_EQ(prism::readImage(dir() / "oiio.exr").pixels, whole.pixels);
}

// --seed draws other samples (pbrt's --seed); tiles draw what the whole image draws under it.
TEST_F(PrismRenderTiles, SeededTilesMergeIntoTheSeededWholeImage) {
    ASSERT_EQ(render("-o " + path("unseeded.exr")).exitCode, 0);
    ASSERT_EQ(render("--seed 99 -o " + path("whole.exr")).exitCode, 0);
    renderTiles(4, " --seed 99");
    ASSERT_EQ(merge(tiles(4) + " -o " + path("merged.exr")).exitCode, 0);
    prism::LoadedImage whole = prism::readImage(dir() / "whole.exr");
    EXPECT_EQ(prism::readImage(dir() / "merged.exr").pixels, whole.pixels);
    EXPECT_NE(prism::readImage(dir() / "unseeded.exr").pixels, whole.pixels);
    int seed = -1;
    for (const auto &[key, value] : whole.metadata.ints)
        if (key == "prism:seed")
            seed = value;
    EXPECT_EQ(seed, 99);
    CliResult bad = render("--seed 16777216 -o " + path("bad.exr"));
    EXPECT_NE(bad.exitCode, 0) << bad.out;
    EXPECT_NE(bad.out.find("--seed"), std::string::npos) << bad.out;
    EXPECT_FALSE(fs::exists(dir() / "bad.exr"));
}

TEST_F(PrismRenderTiles, CropAndPixelBoundsWriteThePartInItsPlace) {
    ASSERT_EQ(render("-o " + path("whole.exr")).exitCode, 0);
    prism::LoadedImage whole = prism::readImage(dir() / "whole.exr");
    // pbrt's rounding: pixels ceil(64 * 0.3) = 20 to ceil(64 * 0.71) = 46, 10 to 34.
    ASSERT_EQ(render("--crop 0.3,0.71,0.2,0.7 -o " + path("crop.exr")).exitCode, 0);
    ASSERT_EQ(render("--pixel-bounds 20,46,10,34 -o " + path("bounds.exr")).exitCode, 0);
    prism::LoadedImage crop = prism::readImage(dir() / "crop.exr");
    EXPECT_EQ(crop.x * 100 + crop.y, 20 * 100 + 10);
    EXPECT_EQ(crop.width * 100 + crop.height, 26 * 100 + 24);
    EXPECT_EQ(crop.pixels, cut(whole, crop));
    EXPECT_EQ(prism::readImage(dir() / "bounds.exr").pixels, crop.pixels);
    // The CPU reference crops the same way (its pixels are its own, not the tracer's).
    CliResult cpu = render("--backend cpu --pixel-bounds 3,9,40,48 -o " + path("cpu.exr"));
    ASSERT_EQ(cpu.exitCode, 0) << cpu.out;
    prism::LoadedImage cpuPart = prism::readImage(dir() / "cpu.exr");
    EXPECT_EQ(cpuPart.x * 100 + cpuPart.y, 3 * 100 + 40);
    EXPECT_EQ(cpuPart.width * 100 + cpuPart.height, 6 * 100 + 8);
    // A PNG holds the part alone.
    ASSERT_EQ(render("--crop 0,0.5,0,0.5 -o " + path("crop.png")).exitCode, 2)
        << "--aov needs an EXR: a usage error";
    CliResult png = prism::test::runTool(
        PRISM_RENDER_EXE, std::string(PRISM_SCENES_DIR) +
                              "/showcase.scene --size 64x48 --quiet --crop 0,0.5,0,0.5 -o " +
                              path("crop.png"));
    ASSERT_EQ(png.exitCode, 0) << png.out;
    EXPECT_EQ(prism::readImage(dir() / "crop.png").width, 32);
}

TEST_F(PrismRenderTiles, BadRegionsAreRefusedBeforeAnyWork) {
    struct Case {
        std::string args, message;
    };
    for (const Case &c : {
             Case{"--crop 0.5,1.2,0,1", "--crop fractions must lie in [0, 1], got 1.2"},
             Case{"--crop 0.6,0.4,0,1", "x0 < x1"},
             Case{"--crop 0.5,1,0", "four comma-separated numbers"},
             Case{"--crop 0.5,1,0,zero", "\"zero\" is not a number"},
             Case{"--pixel-bounds 0,65,0,10", "reach past the 64x48 image"},
             Case{"--pixel-bounds 10,5,0,10", "x0 < x1"},
             Case{"--pixel-bounds 0,1.5,0,10", "is not a pixel coordinate"},
             Case{"--tile 16/16", "tile 16 is out of range: 16 tiles are numbered 0-15"},
             Case{"--tile 3", "--tile takes I/N"},
             Case{"--tile -1/4", "--tile takes I/N"},
             Case{"--tile 0/0", "at least 1 tile"},
             Case{"--tile 0/4 --crop 0,1,0,1", "give one of --crop, --pixel-bounds and --tile"},
         }) {
        SCOPED_TRACE(c.args);
        CliResult r = render(c.args + " -o " + path("x{tile}.exr"));
        EXPECT_EQ(r.exitCode, 2); // a usage error
        EXPECT_EQ(r.out.rfind("prism-render: error: ", 0), 0u) << r.out;
        EXPECT_NE(r.out.find(c.message), std::string::npos) << r.out;
    }
    CliResult png = prism::test::runTool(PRISM_RENDER_EXE, std::string(PRISM_SCENES_DIR) +
                                                               "/showcase.scene --tile 0/4 -o " +
                                                               path("x.png"));
    EXPECT_NE(png.out.find("--tile needs an .exr output"), std::string::npos) << png.out;
    CliResult noTile = render("-o " + path("x{tile}.exr"));
    EXPECT_NE(noTile.out.find("names a {tile}, but no --tile is given"), std::string::npos)
        << noTile.out;
    EXPECT_TRUE(entries().empty()) << "nothing written";
}

TEST_F(PrismRenderTiles, BadTileSetsAreRefusedWithNoOutput) {
    renderTiles(4);
    std::string out = " -o " + path("merged.exr");
    CliResult missing = merge(path("tile0.exr") + " " + path("tile1.exr") + " " +
                              path("tile3.exr") + out);
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.out.find("768 of the 64x48 image's pixels are in no tile given (the "
                               "first: 0,24): is a tile missing?"),
              std::string::npos)
        << missing.out;
    CliResult twice = merge(tiles(4) + " " + path("tile2.exr") + out);
    EXPECT_EQ(twice.exitCode, 1);
    EXPECT_NE(twice.out.find("tile2.exr: pixel 0,24 is also in " + path("tile2.exr")),
              std::string::npos)
        << twice.out;
    ASSERT_EQ(prism::test::runTool(PRISM_RENDER_EXE,
                                   std::string(PRISM_SCENES_DIR) +
                                       "/showcase.scene --size 32x24 --quiet --tile 0/4 -o " +
                                       path("small.exr"))
                  .exitCode,
              0);
    CliResult sizes = merge(tiles(3) + " " + path("small.exr") + out);
    EXPECT_NE(sizes.out.find("small.exr: a tile of a 32x24 image, but"), std::string::npos)
        << sizes.out;
    CliResult itself = merge(tiles(4) + " -o " + path("tile0.exr"));
    EXPECT_NE(itself.out.find("is also one of the tiles"), std::string::npos) << itself.out;
    CliResult none = merge("-o " + path("merged.exr"));
    EXPECT_NE(none.exitCode, 0);
    EXPECT_FALSE(fs::exists(dir() / "merged.exr"));
    CliResult help = merge("--help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("bit for bit"), std::string::npos);
}

} // namespace
