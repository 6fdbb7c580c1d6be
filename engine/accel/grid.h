#pragma once
// A regular grid over the finite primitives (spheres, triangles) of a scene, stored compactly
// (CSR: per-cell offsets + one primitive-id array) for upload to the GPU. Infinite planes stay
// outside it. No Vulkan here.
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

struct GridOptions {
    enum class Mode {
        Auto,  // cells ~ density * primitives, aspect following the bounds
        Off,   // one cell holding everything: every ray tests every primitive
        Fixed, // resolution given by the user
    };
    Mode mode = Mode::Auto;
    glm::ivec3 resolution{1}; // Fixed only
    // Auto only: target cells per primitive (lambda). Measured, see docs/grid-density.md.
    float density = 4.0f;
};

// Parses --grid's argument: "auto", "off", "N" (N^3) or "NxNyNz", each count in 1..1024.
// Throws prism::Error with a message naming the bad text.
GridOptions parseGridOption(std::string_view text);

struct Grid {
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{1.0f};
    glm::ivec3 resolution{1};
    glm::vec3 cellSize{1.0f};
    // Cell (x, y, z) has index x + res.x * (y + res.y * z); its primitives are
    // cellPrimitives[cellStart[i] .. cellStart[i + 1]), ids as in scene/primitive_ids.h.
    std::vector<uint32_t> cellStart;
    std::vector<uint32_t> cellPrimitives;

    uint32_t maxPerCell = 0; // the fullest cell's count, for --stats and the benchmarks

    uint64_t cellCount() const {
        return uint64_t(resolution.x) * uint64_t(resolution.y) * uint64_t(resolution.z);
    }
    uint32_t cellIndex(glm::ivec3 cell) const {
        return uint32_t(cell.x + resolution.x * (cell.y + resolution.y * cell.z));
    }
};

Grid buildGrid(const Scene &scene, const GridOptions &options = {});

} // namespace prism
