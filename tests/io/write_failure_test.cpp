// Failed writes: a clear prism::Error naming the path, and nothing left behind: no
// temporary files, no partial output, an existing file untouched.
#include "core/error.h"
#include "io/image_reader.h"
#include "io/image_writer.h"
#include "read_file.h"
#include "temp_dir_fixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace prism {
namespace {

using WriteFailure = test::TempDirTest;
using test::readFile;

OutputImage smallImage() {
    OutputImage image;
    image.width = 2;
    image.height = 1;
    image.rgba = {0.1f, 0.2f, 0.3f, 1.0f, 0.4f, 0.5f, 0.6f, 1.0f};
    return image;
}

// The message of the prism::Error that `write` throws; fails the test if it throws nothing.
template <typename Write> std::string errorFrom(Write write) {
    try {
        write();
    } catch (const Error &e) {
        return e.what();
    }
    ADD_FAILURE() << "expected prism::Error";
    return {};
}

TEST_F(WriteFailure, UnsupportedExtensionNamesPathAndSupportedFormats) {
    for (const char *name : {"frame.jpg", "frame.tiff", "frame"}) {
        const auto path = dir() / name;
        const std::string message = errorFrom([&] { writeImage(path, smallImage(), {}); });
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find(".exr"), std::string::npos) << message;
        EXPECT_NE(message.find(".png"), std::string::npos) << message;
    }
    EXPECT_TRUE(entries().empty());
}

TEST_F(WriteFailure, MissingDirectoryFailsClearlyAndCreatesNothing) {
    for (const char *name : {"frame.exr", "frame.png"}) {
        const auto path = dir() / "missing" / name;
        const std::string message = errorFrom([&] { writeImage(path, smallImage(), {}); });
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
    }
    EXPECT_TRUE(entries().empty());
}

TEST_F(WriteFailure, MalformedImageIsRejectedBeforeTouchingTheTarget) {
    const auto path = dir() / "frame.exr";
    writeImage(path, smallImage(), {});
    const std::string before = readFile(path);

    OutputImage shortRgba = smallImage();
    shortRgba.rgba.pop_back();
    EXPECT_NE(errorFrom([&] { writeImage(path, shortRgba, {}); }).find("rgba"), std::string::npos);
    OutputImage badDepth = smallImage();
    badDepth.depth = {1.0f};
    EXPECT_NE(errorFrom([&] { writeImage(path, badDepth, {}); }).find("depth"), std::string::npos);
    OutputImage badNormal = smallImage();
    badNormal.normal = {0, 0, 1};
    EXPECT_NE(errorFrom([&] { writeImage(path, badNormal, {}); }).find("normal"),
              std::string::npos);
    OutputImage empty;
    EXPECT_FALSE(errorFrom([&] { writeImage(path, empty, {}); }).empty());

    EXPECT_EQ(readFile(path), before);
    EXPECT_EQ(entries(), std::vector<std::string>{"frame.exr"});
}

TEST_F(WriteFailure, FailedReplaceRemovesTheTemporaryFile) {
    // The target is a non-empty directory: the image is written to the temporary file, and
    // the final rename fails. The temporary file must not survive.
    const auto path = dir() / "busy.exr";
    std::filesystem::create_directory(path);
    std::ofstream(path / "keep.txt") << "kept";

    const std::string message = errorFrom([&] { writeImage(path, smallImage(), {}); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_EQ(entries(), std::vector<std::string>{"busy.exr"});
    EXPECT_EQ(readFile(path / "keep.txt"), "kept");
}

TEST_F(WriteFailure, ReadingAMissingFileNamesIt) {
    const auto path = dir() / "absent.exr";
    const std::string message = errorFrom([&] { readImage(path); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
}

} // namespace
} // namespace prism
