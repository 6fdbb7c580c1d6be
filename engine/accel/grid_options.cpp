// Parsing --grid's argument.
#include <charconv>
#include <string>

#include "accel/grid.h"
#include "accel/grid_resolution.h"
#include "core/error.h"

namespace prism {
namespace {

[[noreturn]] void badGrid(std::string_view text, const std::string &why) {
    throw Error("--grid " + std::string(text) + ": " + why +
                " (expected auto, regular, off, adaptive, two-level, N or NxNyNz with counts 1.." +
                std::to_string(kMaxGridAxisCells) + ")");
}

int parseCount(std::string_view all, std::string_view part) {
    int value = 0;
    auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size())
        badGrid(all, std::string(part).append(" is not a whole number"));
    if (value < 1 || value > kMaxGridAxisCells)
        badGrid(all, std::to_string(value) + " cells is out of range");
    return value;
}

} // namespace

GridOptions parseGridOption(std::string_view text) {
    GridOptions options;
    if (text == "auto")
        return options;
    if (text == "off") {
        options.mode = GridOptions::Mode::Off;
        return options;
    }
    if (text == "regular") {
        options.mode = GridOptions::Mode::Regular;
        return options;
    }
    if (text == "two-level") {
        options.mode = GridOptions::Mode::TwoLevel;
        return options;
    }
    if (text == "adaptive") {
        options.mode = GridOptions::Mode::Adaptive;
        return options;
    }
    options.mode = GridOptions::Mode::Fixed;
    size_t x1 = text.find('x');
    if (x1 == std::string_view::npos) {
        options.resolution = glm::ivec3(parseCount(text, text));
    } else {
        size_t x2 = text.find('x', x1 + 1);
        if (x2 == std::string_view::npos)
            badGrid(text, "give one count or three");
        options.resolution = {parseCount(text, text.substr(0, x1)),
                              parseCount(text, text.substr(x1 + 1, x2 - x1 - 1)),
                              parseCount(text, text.substr(x2 + 1))};
    }
    uint64_t cells = uint64_t(options.resolution.x) * uint64_t(options.resolution.y) *
                     uint64_t(options.resolution.z);
    if (cells > kMaxGridCells)
        badGrid(text,
                std::to_string(cells) + " cells is more than " + std::to_string(kMaxGridCells));
    return options;
}

bool buildsLean(const GridOptions &options, uint64_t finitePrimitives) {
    switch (options.effort) {
    case GridOptions::Effort::Full:
        return false;
    case GridOptions::Effort::Lean:
        return true;
    case GridOptions::Effort::Auto:
        break;
    }
    return options.cameraSamples > 0 &&
           double(options.cameraSamples) < kLeanBelowSamplesPerPrimitive * double(finitePrimitives);
}

GridOptions::Effort parseGridBuild(std::string_view text) {
    if (text == "auto")
        return GridOptions::Effort::Auto;
    if (text == "full")
        return GridOptions::Effort::Full;
    if (text == "lean")
        return GridOptions::Effort::Lean;
    throw Error("--grid-build " + std::string(text) + ": expected auto, full or lean");
}

} // namespace prism
