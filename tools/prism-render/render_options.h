#pragma once
// prism-render's command line, parsed and checked before any work starts.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "accel/grid.h"
#include "render/image_region.h"

namespace prism {

enum class Backend { Vulkan, Cpu };

struct RenderOptions {
    std::filesystem::path scenePath;
    std::filesystem::path outputPath; // with --frames, a pattern (tools/common/frame_range.h)
    std::vector<int> frames;          // --frames; empty: one still (frame 1)
    bool skipExisting = false;        // leave out frames whose output exists
    uint32_t width = 1024, height = 768;
    // --crop, --pixel-bounds or --tile: the pixels to render (empty: the whole image).
    PixelRect region;
    int tileIndex = -1, tileCount = 0; // --tile I/N

    uint32_t samplesPerPixel = 1;
    uint32_t seed = 0; // the sampling seed (shared/sampling.h: samplingKey)
    uint32_t maxDepth = 5;
    GridOptions grid;
    std::string gridText = "auto";
    bool aovDepth = false, aovNormal = false;
    std::string exrCompression = "zip:1"; // --exr-compression, as OpenImageIO names it
    Backend backend = Backend::Vulkan;
    uint32_t repeat = 1;
    bool stats = false;
    bool showTiles = false; // tint tiles by the tracer that ran them (tile_tint.h)
    bool quiet = false;
    bool validation = false;
    std::string deviceFilter;
    // The grid and OBJ cache (accel/grid_cache.h, scene/obj_cache.h): this directory, or none
    // (empty) with --no-cache.
    std::filesystem::path cacheDir;
    std::string commandLine; // as typed, for the image's metadata
};

// Parses argv. Returns false when the program should exit with `exitCode` (help, bad usage);
// messages have been printed then.
bool parseRenderOptions(int argc, char **argv, RenderOptions &options, int &exitCode);

} // namespace prism
