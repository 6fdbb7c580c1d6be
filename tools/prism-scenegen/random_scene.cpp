// prism-scenegen random: the original's rand50 / rand500 / rand5000 benchmark scenes.
#include "generators.h"

#include <vector>

#include "colour.h"
#include "core/error.h"
#include "corner_stage.h"
#include "rng.h"
#include "scene_text.h"

namespace prism::scenegen {
namespace {

enum class Finish { Matte, Glossy, Mirror, Glass };

struct PaletteEntry {
    std::string name;
    Finish finish;
    glm::dvec3 colour;
};

const char *finishName(Finish finish) {
    switch (finish) {
    case Finish::Matte:
        return "matte";
    case Finish::Glossy:
        return "glossy";
    case Finish::Mirror:
        return "mirror";
    default:
        return "glass";
    }
}

// Everything but the colour is fixed per finish: the original's objects had a colour, a
// reflectance and a "refractance"; Blinn-Phong terms make them read as different materials.
const char *finishParameters(Finish finish) {
    switch (finish) {
    case Finish::Matte:
        return "diffuse 0.9 specular 0.1 shininess 16";
    case Finish::Glossy:
        return "diffuse 0.8 specular 0.6 shininess 64";
    case Finish::Mirror:
        return "diffuse 0.35 specular 0.8 shininess 128 reflect 0.6";
    default:
        return "diffuse 0.1 specular 0.9 shininess 200 transmit 0.85 ior 1.5";
    }
}

std::vector<PaletteEntry> randomPalette(Pcg32 &rng, uint32_t size) {
    std::vector<PaletteEntry> palette;
    for (uint32_t i = 0; i < size; ++i) {
        uint32_t roll = rng.below(100); // 40% matte, 30% glossy, 20% mirror, 10% glass
        Finish finish = roll < 40   ? Finish::Matte
                        : roll < 70 ? Finish::Glossy
                        : roll < 90 ? Finish::Mirror
                                    : Finish::Glass;
        double hue = rng.below(3600) / 10.0;
        double saturation = 0.45 + rng.below(4501) / 10000.0;
        double value = 0.55 + rng.below(4001) / 10000.0;
        std::string index = std::to_string(i);
        index.insert(0, index.size() < 2 ? 2 - index.size() : 0, '0');
        palette.push_back({finishName(finish) + index, finish, hsvToRgb(hue, saturation, value)});
    }
    return palette;
}

} // namespace

std::string randomCommand(const RandomOptions &o) {
    return "prism-scenegen random --count " + std::to_string(o.count) + " --seed " +
           std::to_string(o.seed) + " --box " + formatNumber(o.box) + " --min-radius " +
           formatNumber(o.minRadius) + " --max-radius " + formatNumber(o.maxRadius) +
           " --materials " + std::to_string(o.materials);
}

std::string randomScene(const RandomOptions &o, const std::string &command) {
    const int64_t box = toTicks(o.box), minRadius = toTicks(o.minRadius),
                  maxRadius = toTicks(o.maxRadius);
    if (box <= 0 || box > 100'000 * kTicksPerUnit)
        throw Error("--box must be in (0, 100000], got " + formatNumber(o.box));
    if (minRadius <= 0 || maxRadius < minRadius)
        throw Error("need 0 < --min-radius <= --max-radius (to four decimals), got " +
                    formatNumber(o.minRadius) + " and " + formatNumber(o.maxRadius));
    if (2 * maxRadius > box)
        throw Error("--max-radius " + formatNumber(o.maxRadius) +
                    " does not fit in a box of side " + formatNumber(o.box));
    if (o.count == 0 || o.materials == 0)
        throw Error("--count and --materials must be at least 1");

    const double side = double(box) / kTicksPerUnit, half = side / 2.0;
    const int64_t low = -box / 2, high = box + low; // centred on x = z = 0

    SceneText out;
    writeCornerStage(out, side,
                     std::to_string(o.count) + " random spheres in a box of side " +
                         formatNumber(side) + " on a floor, against two walls: one light.",
                     "Recreates the original's rand" + std::to_string(o.count) +
                         " benchmark (N spheres + 3 planes).",
                     command);
    out.line("material wall color 0.75 0.72 0.68");
    out.line("plane 0 0 0 0 1 0 floor");
    out.line("plane 0 0 " + formatNumber(-half) + " 0 0 1 wall");
    out.line("plane " + formatNumber(-half) + " 0 0 1 0 0 wall");
    out.blank();

    Pcg32 rng(o.seed);
    std::vector<PaletteEntry> palette = randomPalette(rng, o.materials);
    for (const PaletteEntry &entry : palette)
        out.line("material " + entry.name + " color " + formatVec(entry.colour) + " " +
                 finishParameters(entry.finish));
    out.blank();
    for (uint32_t i = 0; i < o.count; ++i) {
        int64_t r = rng.between(minRadius, maxRadius);
        int64_t x = rng.between(low + r, high - r);
        int64_t y = rng.between(r, box - r);
        int64_t z = rng.between(low + r, high - r);
        const PaletteEntry &entry = palette[rng.below(o.materials)];
        out.line("sphere " + formatTicks(x) + " " + formatTicks(y) + " " + formatTicks(z) + " " +
                 formatTicks(r) + " " + entry.name);
    }
    return out.str();
}

} // namespace prism::scenegen
