#pragma once
// A check that a load fails with an exact FILE:LINE, as every scene, OBJ and MTL error must.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"

namespace prism::test {

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
