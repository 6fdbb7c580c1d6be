#include "render_options.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>

#include <CLI/CLI.hpp>

#include "cache_option.h"
#include "command_line.h"
#include "core/error.h"
#include "frame_range.h"
#include "render/image_region.h"
#include "render/ray_tracer.h"
#include "shared/gpu_types.h"
#include "size_option.h"
#include "tool_environment.h"

namespace prism {
namespace {

void parseAovs(const std::string &text, RenderOptions &options) {
    size_t start = 0;
    while (start <= text.size()) {
        size_t comma = text.find(',', start);
        std::string name = text.substr(start, comma == std::string::npos ? comma : comma - start);
        if (name == "z")
            options.aovDepth = true;
        else if (name == "normal")
            options.aovNormal = true;
        else
            throw Error("--aov takes a comma-separated list of z and normal, got \"" + text + "\"");
        if (comma == std::string::npos)
            break;
        start = comma + 1;
    }
}

// "A,B,C,D" for --crop and --pixel-bounds; `whole`: each a whole number.
std::array<double, 4> fourNumbers(const std::string &option, const std::string &text, bool whole) {
    std::array<double, 4> v{};
    size_t start = 0;
    for (int k = 0; k < 4; ++k) {
        size_t comma = text.find(',', start);
        if ((k < 3) != (comma != std::string::npos))
            throw Error(option + " takes four comma-separated numbers X0,X1,Y0,Y1, got \"" + text +
                        "\"");
        std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
        char *end = nullptr;
        v[k] = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(v[k]) ||
            (whole && (v[k] != std::floor(v[k]) || v[k] < 0.0 || v[k] > 1e7)))
            throw Error(option + ": \"" + item + "\" is not " +
                        (whole ? "a pixel coordinate (a whole number from 0)" : "a number"));
        start = comma + 1;
    }
    return v;
}

// "I/N": tile I (from 0) of N.
void parseTile(const std::string &text, RenderOptions &options) {
    size_t slash = text.find('/');
    auto whole = [&](const std::string &item) {
        if (item.empty() || item.size() > 6 ||
            item.find_first_not_of("0123456789") != std::string::npos)
            throw Error("--tile takes I/N (tile I, from 0, of N), got \"" + text + "\"");
        return uint32_t(std::stoul(item));
    };
    if (slash == std::string::npos)
        throw Error("--tile takes I/N (tile I, from 0, of N), got \"" + text + "\"");
    options.tileIndex = int(whole(text.substr(0, slash)));
    options.tileCount = int(whole(text.substr(slash + 1)));
}

// --crop, --pixel-bounds or --tile as the pixels to render (at most one of them is given).
void parseRegion(const std::string &crop, const std::string &bounds, const std::string &tile,
                 RenderOptions &options) {
    if (int(!crop.empty()) + int(!bounds.empty()) + int(!tile.empty()) > 1)
        throw Error("give one of --crop, --pixel-bounds and --tile: each picks the region alone");
    if (!crop.empty()) {
        std::array<double, 4> f = fourNumbers("--crop", crop, false);
        options.region = cropWindowPixels(options.width, options.height, f[0], f[1], f[2], f[3]);
    } else if (!bounds.empty()) {
        std::array<double, 4> b = fourNumbers("--pixel-bounds", bounds, true);
        options.region = {uint32_t(b[0]), uint32_t(b[2]), uint32_t(b[1]), uint32_t(b[3])};
        checkPixelBounds(options.region, options.width, options.height);
    } else if (!tile.empty()) {
        parseTile(tile, options);
        options.region = splitTile(options.width, options.height, uint32_t(options.tileIndex),
                                   uint32_t(options.tileCount));
    }
}

std::string lowerExtension(const std::filesystem::path &path) {
    std::string ext = path.extension().string();
    for (char &c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

} // namespace

bool parseRenderOptions(int argc, char **argv, RenderOptions &options, int &exitCode) {
    CLI::App app{"prism-render: renders a .scene file to an EXR (linear float) or PNG (sRGB) "
                 "image with Prism's Vulkan compute ray tracer or its CPU reference."};
    app.set_version_flag("--version", "prism-render 0.1.0");
    std::string scene, output, size = "1024x768", aov, backend = "vulkan";
    app.add_option("SCENE", scene, "Scene file (format: docs/scene-format.md)")->required();
    app.add_option("-o,--output", output,
                   "Output image: .exr (float RGBA + AOVs) or .png; with --frames, a pattern "
                   "whose #### (the frame, zero-padded to the run of #) or {frame} names each "
                   "frame's file")
        ->required();
    std::string frames;
    CLI::Option *framesOption = app.add_option(
        "--frames", frames,
        "Render these frames of the scene's animation in one process (the scene "
        "loaded, its grid built and the tracer compiled once): N, A-B, A-B:STEP or a "
        "comma-separated list of them, e.g. 1-240 or 1,5,10-20");
    app.add_flag("--skip-existing", options.skipExisting,
                 "Leave out frames whose output file exists (images are written whole or not at "
                 "all, so an existing file is a finished frame): resumes a stopped range");
    app.add_option("--size", size, "Image size WxH")->default_val("1024x768");
    std::string crop, pixelBounds, tile;
    app.add_option("--crop", crop,
                   "Render only this part of the image, as fractions X0,X1,Y0,Y1 of its width "
                   "and height (pbrt's --cropwindow: pixels ceil(W*X0) to ceil(W*X1)); an EXR "
                   "keeps the part's place as its data window");
    app.add_option("--pixel-bounds", pixelBounds,
                   "Render only pixels X0 to X1 (excluded), Y0 to Y1 (excluded) of the image");
    app.add_option("--tile", tile,
                   "Render tile I (from 0) of the image split into N tiles on 8-pixel edges, "
                   "as I/N: a farm task's part of a still (prism-merge puts the tiles "
                   "together); {tile} in the output name is replaced by I");
    app.add_option("--spp", options.samplesPerPixel,
                   "Samples per pixel (stratified anti-aliasing, soft shadows)")
        ->check(CLI::Range(1u, kMaxSamplesPerPixel))
        ->default_val(1);
    app.add_option("--seed", options.seed,
                   "Sampling seed: another seed draws another independent set of pixel and "
                   "area-light samples (0, the default, the images Prism has always made); a "
                   "tile or crop draws what the whole image does under the same seed")
        ->check(CLI::Range(0u, gpu::kMaxSeed))
        ->default_val(0);
    app.add_option("--depth", options.maxDepth,
                   "Maximum ray depth: 1 = primary and shadow rays only")
        ->check(CLI::Range(1u, 16u))
        ->default_val(5);
    app.add_option("--grid", options.gridText,
                   "Grid: auto (regular or adaptive, whichever costs the camera's rays less; "
                   "--stats says which and why), regular (sized to the scene), adaptive (cells "
                   "that follow the geometry), two-level (the adaptive grid's one-level ancestor, "
                   "for comparison), off (test every primitive), N (N^3 cells) or NxNyNz")
        ->default_val("auto");
    float density = GridOptions{}.density;
    app.add_option("--grid-density", density,
                   "With --grid auto or regular: the regular grid's target cells per primitive "
                   "(lambda; see "
                   "docs/grid-density.md)")
        ->check(CLI::Range(0.01f, 1000.0f))
        ->default_val(density);
    std::string build = "auto";
    app.add_option(
           "--grid-build", build,
           "How much the grid's build does for the rays: full (adaptive cells grown over "
           "their neighbours, cells holding copies of their triangles: fastest rays), "
           "lean (half the build and a third of a big mesh's memory, rays up to 1.7x "
           "slower at 1M triangles) or auto: lean where the whole image's camera samples (width x "
           "height x spp) are under 4 a primitive, so that one image of a big mesh is "
           "done sooner (a long range of frames of one may want full); --stats says "
           "which (grid_build)")
        ->check(CLI::IsMember({"auto", "full", "lean"}))
        ->default_val("auto");
    app.add_option("--aov", aov, "Extra EXR channels: z (distance, Z), normal (N.X N.Y N.Z)");
    std::string compression = "zip";
    app.add_option("--exr-compression", compression,
                   "An EXR's compression, lossless all: zip (zlib at level 1, the default), "
                   "zips (zlib, one row a block), piz (wavelet: smallest, slowest), rle (fast, "
                   "files ~1.5x zip's) or none (fastest, largest); a range's writes share the "
                   "cores with its next frames")
        ->check(CLI::IsMember({"zip", "zips", "piz", "rle", "none"}))
        ->default_val("zip");
    app.add_option("--backend", backend,
                   "vulkan (GPU or lavapipe) or cpu (double-precision "
                   "reference)")
        ->check(CLI::IsMember({"vulkan", "cpu"}))
        ->default_val("vulkan");
    // --runs, as prism-bench and prism-gridbench name it; --repeat is kept for older scripts.
    app.add_option("--runs,--repeat", options.repeat,
                   "Timed frames (trace_ms is the best); with more than 1, an untimed warm-up "
                   "frame of 1 sample per pixel goes first so that they are alike")
        ->check(CLI::Range(1u, 10000u))
        ->default_val(1);
    app.add_flag("--stats", options.stats, "Print one JSON line of timings and ray counts");
    app.add_flag("--show-tiles", options.showTiles,
                 "Tint each 8x8 tile by the tracer that ran it: as rendered where the full "
                 "tracer did, blue where the one without the grid did (only planes seen, out "
                 "of the geometry's shadows and reflections), grey where the background's did");
    app.add_flag("--quiet", options.quiet, "No progress or warnings on stderr");
    app.add_flag("--validation", options.validation,
                 "Enable Vulkan validation layers (also PRISM_VALIDATION=1)");
    app.add_option("--device", options.deviceFilter,
                   "Use the first Vulkan device whose name contains this text");
    CacheOption cache;
    addCacheOptions(app, cache);
    // Everything below checks the values given: a bad one is a usage error (exit 2).
    std::optional<int> status = parseCommandLine("prism-render", app, argc, argv, [&] {
        options.scenePath = scene;
        options.outputPath = output;
        ImageSize parsed = parseSizeOption(size);
        options.width = parsed.width;
        options.height = parsed.height;
        options.grid = parseGridOption(options.gridText);
        options.grid.density = density;
        options.grid.effort = parseGridBuild(build);
        if (!aov.empty())
            parseAovs(aov, options);
        options.backend = backend == "cpu" ? Backend::Cpu : Backend::Vulkan;
        // zlib's own default level 6 costs a third more time for files 3% smaller.
        options.exrCompression = compression == "zip"    ? "zip:1"
                                 : compression == "zips" ? "zips:1"
                                                         : compression;
        std::string ext = lowerExtension(options.outputPath);
        if (ext != ".exr" && ext != ".png")
            throw Error("output " + output + ": unsupported extension; use .exr or .png");
        if (options.showTiles && options.backend == Backend::Cpu)
            throw Error("--show-tiles shows the Vulkan tracer's tiles; the cpu backend has none");
        if ((options.aovDepth || options.aovNormal) && ext != ".exr")
            throw Error("--aov needs an .exr output (PNG holds colour only)");
        options.cacheDir = cache.resolve();
        if (framesOption->count() > 0) {
            options.frames = parseFrameList(frames);
            if (options.frames.size() > 1 && !hasFrameField(output))
                throw Error("output " + output + " names no frame, but --frames gives " +
                            std::to_string(options.frames.size()) +
                            "; put #### or {frame} in it (e.g. out/shot.####.exr)");
            hasFrameField(output); // an ambiguous pattern is an error even for one frame
            if (options.repeat > 1 && options.frames.size() > 1)
                throw Error("--runs times one frame over and over; give --frames a single frame "
                            "with it, not " +
                            std::to_string(options.frames.size()));
        }
        parseRegion(crop, pixelBounds, tile, options);
        if (options.tileCount > 0 && ext != ".exr")
            throw Error("--tile needs an .exr output: its data window keeps the tile's place for "
                        "prism-merge (PNG cannot)");
        if (output.find("{tile}") != std::string::npos && options.tileCount == 0)
            throw Error("output " + output + " names a {tile}, but no --tile is given");
        options.validation = validationWanted(options.validation);
        options.commandLine = commandLineText(argc, argv);
    });
    if (status) {
        exitCode = *status;
        return false;
    }
    return true;
}

} // namespace prism
