#pragma once
// Helpers for the scene tests: a private temporary directory to write scenes, models and
// images into, and a check that a load fails with an exact FILE:LINE.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace prism::test {

// A fresh directory under the system temp dir, removed with everything in it afterwards.
class TempDir {
public:
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "prism-scene-XXXXXX");
        if (!::mkdtemp(pattern.data()))
            throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir &) = delete;
    TempDir &operator=(const TempDir &) = delete;

    const std::filesystem::path &path() const { return path_; }

    // Writes `bytes` to `relative` (creating directories) and returns the full path.
    std::filesystem::path write(const std::string &relative, std::string_view bytes) const {
        std::filesystem::path file = path_ / relative;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream out(file, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        if (!out)
            throw std::runtime_error("cannot write " + file.string());
        return file;
    }

private:
    std::filesystem::path path_;
};

// Runs `load`, which must throw prism::FileError at `file`:`line` whose message contains
// `fragment`.
inline void expectFileError(const std::function<void()> &load, const std::string &file, int line,
                            const std::string &fragment) {
    try {
        load();
        ADD_FAILURE() << "no error; expected " << file << ":" << line << ": ..." << fragment;
    } catch (const FileError &e) {
        EXPECT_EQ(e.file(), file) << e.what();
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
            << "message '" << e.what() << "' lacks '" << fragment << "'";
        EXPECT_EQ(std::string(e.what()).rfind(file + ":" + std::to_string(line) + ": ", 0), 0u)
            << e.what();
    }
}

} // namespace prism::test
