#pragma once
// prism-view's command line, parsed and checked before a window opens.
#include <cstdint>
#include <filesystem>
#include <string>

#include "accel/grid.h"

namespace prism {

struct ViewScript; // view_script.h: the hidden options of tests and soak runs

// What a user can ask for (the options --help lists).
struct ViewOptions {
    std::filesystem::path scenePath;
    uint32_t width = 1024, height = 768; // window client size at start
    // Samples per pixel the accumulation converges to (with the same strata as prism-render
    // --spp N); one sample is traced per displayed frame until then.
    uint32_t samplesPerPixel = 64;
    uint32_t maxDepth = 5;
    GridOptions grid;
    bool vsync = true;
    // While the camera moves, trace at 1/motionScale of the window's size in each axis (shown
    // magnified); when it stops, at full size. 0 = auto: aim for ~20 frames per second.
    uint32_t motionScale = 0;
    uint32_t benchmarkFrames = 0; // > 0: fly the benchmark path, print JSON, exit
    double frame = 1.0;           // of the scene's animation, at start ([ and ] step it)
    bool validation = false;
    std::string deviceFilter;
    // Built grids and parsed OBJ files are kept here between runs and reloads (--cache), or
    // nowhere (empty: --no-cache).
    std::filesystem::path cacheDir;
    std::string commandLine;
};

// Parses argv into the user's options and the hidden options of a scripted run (`script`, empty
// unless the tests or a soak run asked). Returns false when the program should exit with
// `exitCode` (help, bad usage); messages have been printed then.
bool parseViewOptions(int argc, char **argv, ViewOptions &options, ViewScript &script,
                      int &exitCode);

} // namespace prism
