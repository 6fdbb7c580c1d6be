// prism-scenegen lattice: the original's "grid" benchmark, a regular lattice of spheres.
#include "generators.h"

#include "colour.h"
#include "core/error.h"
#include "corner_stage.h"
#include "scene_text.h"

namespace prism::scenegen {

std::string latticeCommand(const LatticeOptions &o) {
    return "prism-scenegen lattice --size " + std::to_string(o.size) + " --spacing " +
           formatNumber(o.spacing) + " --radius " + formatNumber(o.radius);
}

std::string latticeScene(const LatticeOptions &o, const std::string &command) {
    if (o.size < 1 || o.size > 100)
        throw Error("--size must be in [1, 100], got " + std::to_string(o.size));
    const int64_t spacingTicks = toTicks(o.spacing), radiusTicks = toTicks(o.radius);
    if (spacingTicks <= 0 || spacingTicks > 1000 * kTicksPerUnit)
        throw Error("--spacing must be in (0, 1000], got " + formatNumber(o.spacing));
    if (radiusTicks <= 0 || 2 * radiusTicks > spacingTicks)
        throw Error("--radius must be in (0, spacing / 2] so that spheres neither overlap nor "
                    "cut the floor, got " +
                    formatNumber(o.radius));

    const uint32_t n = o.size;
    const double spacing = double(spacingTicks) / kTicksPerUnit;
    const double radius = double(radiusTicks) / kTicksPerUnit;
    const double side = n * spacing; // the lattice fills a cube of this side above the floor

    SceneText out;
    writeCornerStage(out, side,
                     std::to_string(n) + " x " + std::to_string(n) + " x " + std::to_string(n) +
                         " lattice of spheres above a floor, one colour per layer: one light.",
                     "Recreates the original's grid benchmark (" + std::to_string(n * n * n) +
                         " spheres + 1 plane).",
                     command);
    out.line("plane 0 0 0 0 1 0 floor");
    out.blank();
    // Bottom layer red, top layer violet: a spectrum, as a prism would split it.
    for (uint32_t j = 0; j < n; ++j) {
        double hue = n > 1 ? 270.0 * j / (n - 1) : 0.0;
        out.line("material layer" + std::to_string(j) + " color " +
                 formatVec(hsvToRgb(hue, 0.75, 0.9)) +
                 " diffuse 0.8 specular 0.5 shininess 48 reflect 0.15");
    }
    for (uint32_t j = 0; j < n; ++j) {
        out.blank();
        out.line("use layer" + std::to_string(j));
        double y = spacing / 2.0 + j * spacing;
        for (uint32_t k = 0; k < n; ++k)
            for (uint32_t i = 0; i < n; ++i) {
                double x = (i - (n - 1) / 2.0) * spacing;
                double z = (k - (n - 1) / 2.0) * spacing;
                out.line("sphere " + formatVec({x, y, z}) + " " + formatNumber(radius));
            }
    }
    return out.str();
}

} // namespace prism::scenegen
