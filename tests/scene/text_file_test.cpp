// readTextFile gives a file's bytes exactly, whether it has a size (a regular file, read in one
// call) or not (a pipe, read as a stream), and names the file when it cannot.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <thread>

#include "core/error.h"
#include "scene/text_file.h"
#include "temp_dir.h"

namespace prism {
namespace {

std::string someBytes(size_t n) {
    std::string bytes(n, '\0');
    for (size_t i = 0; i < n; ++i)
        bytes[i] = char((i * 131 + i / 7) & 0xff); // NULs and line ends among them
    return bytes;
}

TEST(TextFile, RegularFilesAreReadWhole) {
    test::TempDir dir;
    for (size_t n : {size_t(0), size_t(1), size_t(4096), size_t(9) << 20}) {
        std::filesystem::path path = dir.path() / std::to_string(n); // named by its size
        std::string bytes = someBytes(n);
        std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(n));
        EXPECT_EQ(readTextFile(path, "test file"), bytes) << n << " bytes";
    }
}

TEST(TextFile, PipesAreReadToTheirEnd) {
    test::TempDir dir;
    std::filesystem::path fifo = dir.path() / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string bytes = someBytes(300'000); // more than a pipe's buffer
    std::thread writer([&] {
        std::ofstream(fifo, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    });
    std::string read = readTextFile(fifo, "test pipe");
    writer.join();
    EXPECT_EQ(read, bytes);
}

TEST(TextFile, MissingFilesAndDirectoriesAreNamedInTheError) {
    test::TempDir dir;
    try {
        readTextFile(dir.path() / "absent.obj", "OBJ file");
        FAIL() << "no error";
    } catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("cannot read OBJ file"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("absent.obj"), std::string::npos);
    }
    EXPECT_THROW(readTextFile(dir.path(), "scene file"), Error);
}

} // namespace
} // namespace prism
