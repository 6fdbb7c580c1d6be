#pragma once
// One configuration of the tracer that a benchmark compares with others on the same scene:
// a grid choice and switched-off features, written as e.g. "grid=20", "density=4",
// "off", "no-shadows", "storage" or combinations joined by '+' ("grid=30+no-reflection").
// For the studies (docs/studies) only, methods Prism replaced: "offset=E" (a fixed ray offset
// of E scene units, as the original had; "offset=relative" is Prism's) and "triangle=mt"
// (Moller-Trumbore; "triangle=watertight" is Prism's). "flat" writes a scene's instances out as
// plain triangles first (what instancing saves, in memory and in time).
#include <string>

#include "accel/grid.h"
#include "render/ray_tracer.h"

namespace prism {

struct BenchVariant {
    std::string name;
    GridOptions grid;
    TracerOptions tracer;
    bool flattenInstances = false;
};

// Throws prism::Error naming the bad token.
BenchVariant parseBenchVariant(const std::string &text);

} // namespace prism
