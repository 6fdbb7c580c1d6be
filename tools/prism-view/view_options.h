#pragma once
// prism-view's command line, parsed and checked before a window opens.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "accel/grid.h"

namespace prism {

// Test hook: at frame `frame` (0-based), ask the window manager for this client size.
struct ScriptedResize {
    uint32_t frame = 0;
    uint32_t width = 0, height = 0;
};

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
    bool validation = false;
    std::string deviceFilter;
    std::string commandLine;

    // Scripted runs (tests, soak): no input, a fixed number of frames, then exit.
    uint32_t scriptFrames = 0;
    std::vector<ScriptedResize> resizes;
    bool scriptOrbit = false;             // move the camera every frame (soak test)
    std::filesystem::path screenshotPath; // written (EXR + PNG) when the script ends
    uint32_t reloadFrame = 0;             // at this frame the scene file is replaced by
    std::filesystem::path reloadPath;     // this one and reloaded (as if edited)
    uint32_t reportEvery = 0;             // soak: print RSS every N frames
};

// Parses argv. Returns false when the program should exit with `exitCode` (help, bad usage);
// messages have been printed then.
bool parseViewOptions(int argc, char **argv, ViewOptions &options, int &exitCode);

} // namespace prism
