// EXR output: float channels come back bit for bit, in place, with their names and with
// every metadata attribute.
#include "core/error.h"
#include "io/image_reader.h"
#include "io/image_writer.h"
#include "temp_dir_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace prism {
namespace {

using ExrWrite = test::TempDirTest;

int channelIndex(const LoadedImage &image, const std::string &name) {
    auto it = std::find(image.channelNames.begin(), image.channelNames.end(), name);
    return it == image.channelNames.end() ? -1 : static_cast<int>(it - image.channelNames.begin());
}

float channelAt(const LoadedImage &image, const std::string &name, int x, int y) {
    const int c = channelIndex(image, name);
    EXPECT_GE(c, 0) << "no channel " << name;
    return image.pixels[(static_cast<std::size_t>(y) * image.width + x) * image.channels + c];
}

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// A 3x2 image of awkward floats (denormal, -0, inf depth, beyond half range), distinct per pixel.
OutputImage awkwardImage() {
    const float inf = std::numeric_limits<float>::infinity();
    OutputImage image;
    image.width = 3;
    image.height = 2;
    image.rgba = {0.0f,    1.0f,     -0.25f, 1.0f,  // (0,0)
                  1e-40f,  3.4e38f,  0.1f,   0.5f,  // (1,0): denormal, near FLT_MAX
                  -0.0f,   1.0f / 3, 2.5f,   0.0f,  // (2,0)
                  7.0f,    123.456f, 1e-7f,  1.0f,  // (0,1)
                  0.3f,    0.6f,     0.9f,   0.75f, // (1,1)
                  65504.f, 65505.f,  1e5f,   1.0f}; // (2,1): beyond half range
    image.depth = {1.5f, inf, 0.0f, 1e30f, 2.25f, inf};
    image.normal = {0, 0, 1, 1, 0, 0, 0, -1, 0, 0.6f, 0.8f, 0, -0.6f, 0, 0.8f, 0, 0, -1};
    return image;
}

TEST_F(ExrWrite, RoundTripsRgbaDepthAndNormalsExactly) {
    const OutputImage image = awkwardImage();
    const auto path = dir() / "frame.exr";
    writeImage(path, image, {});

    const LoadedImage back = readImage(path);
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    ASSERT_EQ(back.channels, 8);
    const char *rgba[] = {"R", "G", "B", "A"};
    const char *normal[] = {"N.X", "N.Y", "N.Z"};
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            const int i = y * 3 + x;
            for (int k = 0; k < 4; ++k)
                EXPECT_TRUE(sameBits(channelAt(back, rgba[k], x, y), image.rgba[i * 4 + k]))
                    << rgba[k] << " at " << x << "," << y;
            EXPECT_TRUE(sameBits(channelAt(back, "Z", x, y), image.depth[i]))
                << "Z at " << x << "," << y;
            for (int k = 0; k < 3; ++k)
                EXPECT_TRUE(sameBits(channelAt(back, normal[k], x, y), image.normal[i * 3 + k]))
                    << normal[k] << " at " << x << "," << y;
        }
    }
    EXPECT_TRUE(std::isinf(channelAt(back, "Z", 1, 0)));
}

TEST_F(ExrWrite, WritesOnlyRgbaWhenDepthAndNormalsAreAbsent) {
    OutputImage image = awkwardImage();
    image.depth.clear();
    image.normal.clear();
    writeImage(dir() / "plain.exr", image, {});

    const LoadedImage back = readImage(dir() / "plain.exr");
    EXPECT_EQ(back.channelNames, (std::vector<std::string>{"R", "G", "B", "A"}));
    EXPECT_TRUE(sameBits(channelAt(back, "G", 1, 0), 3.4e38f));
}

TEST_F(ExrWrite, StoresMetadataAsTypedHeaderAttributes) {
    ImageMetadata meta;
    meta.strings = {{"prism:device", "llvmpipe (LLVM 15.0.6, 256 bits)"},
                    {"prism:commandLine", "prism-render scenes/a b.scene -o \"out.exr\""}};
    meta.floats = {{"prism:renderTimeMs", 12.625f}, {"prism:gridCellSize", 1e-3f}};
    meta.ints = {{"prism:gridResolution", 64}, {"prism:raysPrimary", 786432}};
    writeImage(dir() / "meta.exr", awkwardImage(), meta);

    const ImageMetadata back = readImage(dir() / "meta.exr").metadata;
    auto has = [](const auto &list, const auto &entry) {
        return std::find(list.begin(), list.end(), entry) != list.end();
    };
    for (const auto &entry : meta.strings)
        EXPECT_TRUE(has(back.strings, entry)) << entry.first;
    for (const auto &entry : meta.floats)
        EXPECT_TRUE(has(back.floats, entry)) << entry.first;
    for (const auto &entry : meta.ints)
        EXPECT_TRUE(has(back.ints, entry)) << entry.first;
}

TEST_F(ExrWrite, ReplacesAnExistingFileAndLeavesNoTemporaryFiles) {
    OutputImage first = awkwardImage();
    writeImage(dir() / "frame.exr", first, {});
    OutputImage second = first;
    second.rgba[0] = 42.0f;
    second.depth.clear();
    writeImage(dir() / "frame.exr", second, {});

    const LoadedImage back = readImage(dir() / "frame.exr");
    EXPECT_EQ(channelAt(back, "R", 0, 0), 42.0f);
    EXPECT_EQ(channelIndex(back, "Z"), -1);
    EXPECT_EQ(entries(), std::vector<std::string>{"frame.exr"});
}

TEST_F(ExrWrite, AcceptsAnUpperCaseExtension) {
    writeImage(dir() / "FRAME.EXR", awkwardImage(), {});
    EXPECT_EQ(readImage(dir() / "FRAME.EXR").channels, 8);
}

std::string stringAttribute(const LoadedImage &image, const std::string &name) {
    for (const auto &[key, value] : image.metadata.strings)
        if (key == name)
            return value;
    return "";
}

TEST_F(ExrWrite, EveryCompressionOnOfferIsLosslessAndNamedInTheHeader) {
    OutputImage image = awkwardImage();
    writeImage(dir() / "zip.exr", image, {});
    const LoadedImage reference = readImage(dir() / "zip.exr");
    EXPECT_EQ(stringAttribute(reference, "compression"), "zip");
    for (const char *compression : {"zips:1", "piz", "rle", "none"}) {
        image.exrCompression = compression;
        std::string name = std::string(compression).substr(0, 4);
        writeImage(dir() / (name + ".exr"), image, {});
        const LoadedImage back = readImage(dir() / (name + ".exr"));
        EXPECT_EQ(stringAttribute(back, "compression"), std::string(compression).substr(0, 4))
            << compression;
        ASSERT_EQ(back.pixels.size(), reference.pixels.size());
        for (size_t k = 0; k < back.pixels.size(); ++k)
            ASSERT_TRUE(sameBits(back.pixels[k], reference.pixels[k])) << compression << " " << k;
    }
}

TEST_F(ExrWrite, ALossyOrUnknownCompressionIsRefusedBeforeAnyFile) {
    OutputImage image = awkwardImage();
    for (const char *compression : {"b44", "dwaa", "pxr24", "zip:6x", ""}) {
        image.exrCompression = compression;
        try {
            writeImage(dir() / "lossy.exr", image, {});
            ADD_FAILURE() << compression << " was accepted";
        } catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find("is not one of the lossless"), std::string::npos)
                << e.what();
        }
    }
    EXPECT_FALSE(std::filesystem::exists(dir() / "lossy.exr"));
}

} // namespace
} // namespace prism
