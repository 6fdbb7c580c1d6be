#pragma once
// A private temporary directory, removed with everything in it afterwards: tests write scenes,
// models and images into it and can list exactly what a step left behind.
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace prism::test {

class TempDir {
public:
    // mkdtemp, not a name made from the pid and test name: unique even when several test
    // processes run side by side, and created empty by construction.
    TempDir() {
        std::string pattern = std::filesystem::temp_directory_path() / "prism-test-XXXXXX";
        if (!::mkdtemp(pattern.data()))
            throw std::runtime_error(std::string("mkdtemp failed: ") + std::strerror(errno));
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored; // a destructor must not throw; a leftover in /tmp is harmless
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

    // Names of every entry directly inside, hidden ones included, sorted: what a test compares
    // to prove nothing else (temporary or partial files) was left.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto &entry : std::filesystem::directory_iterator(path_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    std::filesystem::path path_;
};

} // namespace prism::test
