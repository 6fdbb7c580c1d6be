// prism-merge: the tiles of a still (prism-render --tile I/N) into the whole image. See --help.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command_line.h"
#include "core/error.h"
#include "tile_merge.h"

namespace {

int run(int argc, char **argv) {
    CLI::App app{"prism-merge: puts the tiles of one still (prism-render --tile I/N, or EXR "
                 "regions from --crop / --pixel-bounds) back together into the whole image. "
                 "The tiles must cover the image exactly once; the result is bit for bit the "
                 "image one process would have rendered."};
    app.set_version_flag("--version", "prism-merge 0.1.0");
    std::vector<std::string> tiles;
    std::string output;
    bool quiet = false;
    app.add_option("TILES", tiles, "The tiles: EXR files written by prism-render")
        ->required()
        ->check(CLI::ExistingFile);
    app.add_option("-o,--output", output,
                   "The whole image: .exr (every channel of the tiles) or .png (colour, sRGB)")
        ->required();
    app.add_flag("--quiet", quiet, "No summary line on stderr");
    if (auto status = prism::parseCommandLine("prism-merge", app, argc, argv))
        return *status;
    std::vector<std::filesystem::path> paths(tiles.begin(), tiles.end());
    std::error_code ec;
    for (const std::filesystem::path &p : paths)
        if (std::filesystem::equivalent(p, output, ec))
            throw prism::Error("the output " + output + " is also one of the tiles");
    prism::MergedImage merged = prism::mergeTiles(paths);
    std::string ext = std::filesystem::path(output).extension().string();
    if (ext == ".png" || ext == ".PNG") { // colour only
        merged.image.depth.clear();
        merged.image.normal.clear();
    }
    prism::writeImage(output, merged.image, merged.metadata);
    if (!quiet)
        std::fprintf(stderr, "prism-merge: %zu tiles -> %s (%dx%d)\n", paths.size(),
                     output.c_str(), merged.image.width, merged.image.height);
    return 0;
}

} // namespace

int main(int argc, char **argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "prism-merge: error: %s\n", e.what());
    }
    return 1;
}
