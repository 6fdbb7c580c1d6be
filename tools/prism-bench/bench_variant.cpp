#include "bench_variant.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace prism {
namespace {

// The number after "key=" in a variant: a finite float > 0, or an Error naming the variant.
float parsePositive(const std::string &variant, const std::string &value, const char *key) {
    float number = 0.0f;
    auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
    if (ec != std::errc() || end != value.data() + value.size() || !(number > 0.0f) ||
        !std::isfinite(number))
        throw Error("variant " + variant + ": " + key + " must be a positive number, not '" +
                    value + "'");
    return number;
}

// A whole number from 1 to 2^31.
size_t parseCount(const std::string &variant, const std::string &value, const char *key) {
    size_t number = 0;
    auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
    if (ec != std::errc() || end != value.data() + value.size() || number == 0 ||
        number > (size_t(1) << 31))
        throw Error("variant " + variant + ": " + key +
                    " must be a whole number from 1 to 2^31, not '" + value + "'");
    return number;
}

} // namespace

BenchVariant parseBenchVariant(const std::string &text) {
    BenchVariant v;
    v.name = text;
    std::stringstream tokens(text);
    std::string token;
    while (std::getline(tokens, token, '+')) {
        if (token == "auto" || token == "regular" || token == "off" || token == "adaptive" ||
            token == "two-level") {
            v.grid.mode = parseGridOption(token).mode;
        } else if (token.rfind("grid=", 0) == 0) {
            float density = v.grid.density;
            v.grid = parseGridOption(token.substr(5));
            v.grid.density = density;
        } else if (token.rfind("density=", 0) == 0) {
            v.grid.density = parsePositive(text, token.substr(8), "density");
        } else if (token == "lean") {
            v.grid.effort = GridOptions::Effort::Lean;
        } else if (token == "no-reflection") {
            v.tracer.reflection = false;
        } else if (token == "no-refraction") {
            v.tracer.transmission = false;
        } else if (token == "no-shadows") {
            v.tracer.shadows = false;
        } else if (token == "no-cull") {
            v.tracer.cullMissTiles = false;
        } else if (token == "no-plane-tiles") {
            v.tracer.cullPlaneTiles = false;
        } else if (token == "no-tile-starts") {
            v.tracer.tileStarts = false;
        } else if (token == "bit-reversed-rows") {
            v.tracer.rowsByThread = false;
        } else if (token.rfind("start-boxes=", 0) == 0) {
            v.tracer.maxStartBoxes = parseCount(text, token.substr(12), "start-boxes");
        } else if (token == "no-cell-primitives") {
            v.tracer.cellPrimitives = false;
        } else if (token == "no-fold") {
            v.tracer.foldSpecialization = false;
        } else if (token == "resumable") {
            v.tracer.resumable = true;
        } else if (token == "texel" || token == "storage") {
            v.tracer.texelBuffers = token == "texel";
        } else if (token == "offset=relative") {
            v.tracer.fixedRayOffset = 0.0f;
        } else if (token.rfind("offset=", 0) == 0) {
            v.tracer.fixedRayOffset = parsePositive(text, token.substr(7), "offset");
        } else if (token == "flat") {
            v.flattenInstances = true;
        } else if (token == "triangle=watertight" || token == "triangle=mt") {
            v.tracer.mollerTrumbore = token == "triangle=mt";
        } else {
            throw Error("variant " + text + ": unknown part '" + token +
                        "' (use auto, regular, off, adaptive, two-level, grid=N|NxNyNz, density=L, "
                        "lean, no-reflection, no-refraction, no-shadows, no-cull, no-plane-tiles, "
                        "no-tile-starts, start-boxes=N, bit-reversed-rows, "
                        "no-cell-primitives, no-fold, texel, "
                        "storage, "
                        "resumable, offset=relative|E, triangle=watertight|mt, flat; join with +)");
        }
    }
    return v;
}

} // namespace prism
