#pragma once
// Reading whole input files (scene, OBJ, MTL) into memory.
#include <filesystem>
#include <string>

namespace prism {

// The file's bytes. Throws prism::Error("cannot read WHAT 'PATH': reason") when it cannot.
std::string readTextFile(const std::filesystem::path &path, const char *what);

// How a path is shown in messages: lexically normalised, '/' separators.
std::string displayPath(const std::filesystem::path &path);

// A path written in an input file, relative to the directory `baseDir` of that file.
// Backslashes become '/' so files written on Windows work.
std::filesystem::path resolveInputPath(const std::filesystem::path &baseDir, std::string written);

} // namespace prism
