#include "view_options.h"

#include <cstdlib>
#include <optional>

#include <CLI/CLI.hpp>

#include "cache_option.h"
#include "command_line.h"
#include "core/error.h"
#include "render/ray_tracer.h"
#include "size_option.h"
#include "tool_environment.h"
#include "view_script.h"

namespace prism {

bool parseViewOptions(int argc, char **argv, ViewOptions &options, ViewScript &script,
                      int &exitCode) {
    CLI::App app{"prism-view: flies through a .scene file in a window, ray traced by Prism's "
                 "Vulkan compute tracer. While the camera is still, samples accumulate."};
    app.set_version_flag("--version", "prism-view 0.1.0");
    std::string scene, size = "1024x768", grid = "auto", vsync = "on";
    app.add_option("SCENE", scene, "Scene file (format: docs/scene-format.md)")->required();
    app.add_option("--size", size, "Window size WxH (the traced image follows the window)")
        ->default_val("1024x768");
    app.add_option("--spp", options.samplesPerPixel,
                   "Samples per pixel to converge to while the camera is still (one per frame; "
                   "the same strata as prism-render --spp N)")
        ->check(CLI::Range(1u, kMaxSamplesPerPixel))
        ->default_val(options.samplesPerPixel);
    app.add_option("--depth", options.maxDepth,
                   "Maximum ray depth: 1 = primary and shadow rays only")
        ->check(CLI::Range(1u, 16u))
        ->default_val(5);
    app.add_option("--grid", grid,
                   "Grid: auto (regular or adaptive, by cost), regular, adaptive, two-level, off "
                   "(test every "
                   "primitive), N (N^3 cells) or NxNyNz")
        ->default_val("auto");
    float density = GridOptions{}.density;
    app.add_option("--grid-density", density,
                   "With --grid auto or regular: the regular grid's target cells per primitive "
                   "(docs/grid-density.md)")
        ->check(CLI::Range(0.01f, 1000.0f))
        ->default_val(density);
    app.add_option("--vsync", vsync,
                   "on: wait for the display (FIFO); off: mailbox or immediate where the device "
                   "has one")
        ->check(CLI::IsMember({"on", "off"}))
        ->default_val("on");
    std::string motionScale = "auto";
    app.add_option("--motion-scale", motionScale,
                   "While the camera moves, trace at 1/N of the window size (auto: aim for ~20 "
                   "FPS from the speed of still frames; 1: always full size)")
        ->default_val("auto");
    app.add_option("--benchmark", options.benchmarkFrames,
                   "Fly a fixed camera path for N frames without input (vsync off), print one "
                   "JSON line of frame times and Mrays/s, exit")
        ->check(CLI::Range(1u, 1000000u));
    app.add_option("--frame", options.frame,
                   "Show this frame of the scene's animation (its camera keys or turntable, and "
                   "instances moved by keys); [ and ] step back and forward a frame")
        ->check(CLI::Range(1.0, 1e9))
        ->default_val(1);
    app.add_flag("--validation", options.validation,
                 "Enable Vulkan validation layers (also PRISM_VALIDATION=1); any message makes "
                 "the exit status 1");
    app.add_option("--device", options.deviceFilter,
                   "Use the first Vulkan device whose name contains this text");
    CacheOption cache;
    addCacheOptions(app, cache);
    ViewScriptOptions scriptOptions(app); // for tests and soak runs; not in --help
    // Everything below checks the values given: a bad one is a usage error (exit 2).
    std::optional<int> status = parseCommandLine("prism-view", app, argc, argv, [&] {
        options.scenePath = scene;
        ImageSize parsed = parseSizeOption(size);
        options.width = parsed.width;
        options.height = parsed.height;
        options.grid = parseGridOption(grid);
        options.grid.density = density;
        options.vsync = vsync == "on" && options.benchmarkFrames == 0;
        if (motionScale != "auto") {
            if (motionScale.empty() || motionScale.size() > 1 || motionScale[0] < '1' ||
                motionScale[0] > '8')
                throw Error("--motion-scale takes auto or 1..8, got \"" + motionScale + "\"");
            options.motionScale = uint32_t(motionScale[0] - '0');
        }
        options.cacheDir = cache.resolve();
        script = scriptOptions.script();
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
