#pragma once
// For TEST_F suites in which every test works in a directory of its own: GoogleTest builds a
// fresh fixture, and so a fresh TempDir, for each test.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "temp_dir.h"

namespace prism::test {

class TempDirTest : public ::testing::Test {
protected:
    const std::filesystem::path &dir() const { return temp_.path(); }
    std::filesystem::path write(const std::string &relative, std::string_view bytes) const {
        return temp_.write(relative, bytes);
    }
    std::vector<std::string> entries() const { return temp_.entries(); }

private:
    TempDir temp_;
};

} // namespace prism::test
