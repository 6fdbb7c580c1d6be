#pragma once
// The metadata every image a Prism tool writes carries (EXR attributes, PNG text chunks), so
// an image says how it was made whichever tool made it.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "accel/grid.h"
#include "core/ray_counts.h"
#include "io/image_metadata.h"
#include "session/render_stats.h" // gridText

namespace prism {

struct RenderRecord {
    std::string commandLine; // as typed
    std::string scenePath;
    std::string device;
    std::string backend;        // "vulkan" or "cpu"
    std::string gridResolution; // gridText(grid), or why there is none
    std::string gridChoice;     // Grid::choice: what --grid auto chose, and why
    uint64_t gridCells = 0, gridBytes = 0;
    // The grid's work per primary ray, counted on the CPU (accel/walk_counts.h); lower bounds
    // where counting stopped.
    double gridCellsPerPrimaryRay = 0.0, gridTestsPerPrimaryRay = 0.0;
    RayCounts rays;            // of one frame
    double renderTimeMs = 0.0; // best frame
    double renderTimeMedianMs = 0.0;
    double gridBuildMs = 0.0;
    double mraysPerSecond = 0.0;
    uint32_t samplesPerPixel = 1;
    uint32_t maxDepth = 5;
    uint32_t seed = 0; // the sampling seed (prism:seed)
    int frame = -1; // the animation frame (prism:frame), written when >= 0: --frames renders
    // A part of the image (prism:region "x0,x1,y0,y1" in pixels, render/image_region.h) and
    // the tile it is (prism:tile "I/N"), written when not empty.
    std::string region, tile;
};

ImageMetadata renderMetadata(const RenderRecord &record);

} // namespace prism
