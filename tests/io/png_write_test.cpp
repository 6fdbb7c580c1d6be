// PNG output: 8-bit RGB with the exact sRGB curve, clamped and rounded to nearest.
#include "io/image_reader.h"
#include "io/image_writer.h"
#include "temp_dir_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace prism {
namespace {

using PngWrite = test::TempDirTest;

// One row of linear values, grey (R = G = B), alpha varying to show it is ignored.
OutputImage greyRow(const std::vector<float> &linear) {
    OutputImage image;
    image.width = static_cast<int>(linear.size());
    image.height = 1;
    for (std::size_t i = 0; i < linear.size(); ++i)
        image.rgba.insert(image.rgba.end(),
                          {linear[i], linear[i], linear[i], static_cast<float>(i % 2)});
    return image;
}

TEST_F(PngWrite, EncodesLinearValuesAsEightBitSrgb) {
    // 0.18 -> 0.46136 * 255 = 117.65; 0.002 -> 12.92 * 0.002 * 255 = 6.59 (linear segment).
    const std::vector<float> linear = {0.0f, 1.0f, 0.5f, 0.18f, 0.002f, 1.5f, 1e6f, -0.5f};
    const std::vector<int> expected = {0, 255, 188, 118, 7, 255, 255, 0};
    writeImage(dir() / "grey.png", greyRow(linear), {});

    const LoadedImage back = readImage(dir() / "grey.png");
    ASSERT_EQ(back.channels, 3);
    ASSERT_EQ(back.width, static_cast<int>(linear.size()));
    EXPECT_EQ(back.channelNames, (std::vector<std::string>{"R", "G", "B"}));
    for (std::size_t i = 0; i < linear.size(); ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(std::lround(back.pixels[i * 3 + k] * 255.0f), expected[i])
                << "linear " << linear[i] << " channel " << k;
}

TEST_F(PngWrite, KeepsChannelsAndRowsInPlace) {
    OutputImage image;
    image.width = 2;
    image.height = 2;
    image.rgba = {1, 0, 0, 1, 0, 1, 0, 1,  // top: red, green
                  0, 0, 1, 1, 1, 1, 1, 1}; // bottom: blue, white
    writeImage(dir() / "quad.png", image, {});

    const LoadedImage back = readImage(dir() / "quad.png");
    const std::vector<float> expected = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    EXPECT_EQ(back.pixels, expected);
}

TEST_F(PngWrite, StoresMetadataAsText) {
    ImageMetadata meta;
    meta.strings = {{"prism:device", "llvmpipe"}};
    meta.floats = {{"prism:renderTimeMs", 0.1f}};
    meta.ints = {{"prism:gridResolution", 32}};
    writeImage(dir() / "meta.png", greyRow({0.5f}), meta);

    const auto strings = readImage(dir() / "meta.png").metadata.strings;
    auto has = [&](const std::string &name, const std::string &value) {
        return std::find(strings.begin(), strings.end(), std::pair{name, value}) != strings.end();
    };
    EXPECT_TRUE(has("prism:device", "llvmpipe"));
    EXPECT_TRUE(has("prism:renderTimeMs", "0.1")); // shortest text that reads back exactly
    EXPECT_TRUE(has("prism:gridResolution", "32"));
}

} // namespace
} // namespace prism
