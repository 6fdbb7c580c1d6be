#include "bench_variant.h"

#include <charconv>
#include <sstream>

#include "core/error.h"

namespace prism {

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
            std::string value = token.substr(8);
            float density = 0.0f;
            auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), density);
            if (ec != std::errc() || end != value.data() + value.size() || !(density > 0.0f))
                throw Error("variant " + text + ": density must be a positive number");
            v.grid.density = density;
        } else if (token == "no-reflection") {
            v.tracer.reflection = false;
        } else if (token == "no-refraction") {
            v.tracer.transmission = false;
        } else if (token == "no-shadows") {
            v.tracer.shadows = false;
        } else if (token == "resumable") {
            v.tracer.resumable = true;
        } else if (token == "texel" || token == "storage") {
            v.tracer.texelBuffers = token == "texel";
        } else {
            throw Error("variant " + text + ": unknown part '" + token +
                        "' (use auto, regular, off, adaptive, two-level, grid=N|NxNyNz, density=L, "
                        "no-reflection, "
                        "no-refraction, no-shadows, texel, storage, resumable; join with +)");
        }
    }
    return v;
}

} // namespace prism
