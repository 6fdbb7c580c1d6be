#pragma once
// What a grid costs the tracer, counted on the CPU: a lattice of the scene camera's primary rays
// walks the grid as the shader does (accel/grid_walk.h), testing each cell's primitives until
// the nearest hit lies in the cell reached. The counts are the tracer's work per ray, exactly,
// for those rays; --stats reports them, and `--grid auto` compares grids with them.
#include <limits>
#include <vector>

#include "accel/grid.h"
#include "scene/scene.h"

namespace prism {

struct WalkCounts {
    uint32_t rays = 0;
    double cellsPerRay = 0.0; // cells visited
    double testsPerRay = 0.0; // primitive tests
    // Counting stopped early (see countWalks): the figures are lower bounds.
    bool stopped = false;
    // Each walked ray's nearest hit (infinity: a miss), in the lattice's order: the same for
    // every grid over the scene, so a grid not built yet can be priced by them (below).
    std::vector<double> nearestHits;
};

// Rays through the pixel centres of a `columns` wide image of the given aspect (width / height).
// Stops as soon as the tests counted exceed stopAboveTestsPerRay for every ray of the lattice:
// a grid that crowds the camera's rays costs seconds to count in full, and a lower bound is
// all a comparison needs.
WalkCounts countWalks(const Scene &scene, const Grid &grid, double aspect, int columns = 48,
                      double stopAboveTestsPerRay = std::numeric_limits<double>::infinity());
// Lower bounds on what `layout` (a regular grid's box and resolution, no cells: it need not be
// built) would cost the same rays as countWalks(scene, ..., aspect, columns) that found
// `nearestHits`: each ray visits at least the cells it crosses up to its nearest hit (one
// fewer, for a hit on a cell face) and tests at least the primitive it hits. `stopped` is set:
// the figures are lower bounds.
WalkCounts lowerBoundWalks(const Scene &scene, const Grid &layout, double aspect, int columns,
                           const std::vector<double> &nearestHits);
// The same for `camera` (an animated scene's frame) instead of the scene's own.
WalkCounts countWalks(const Scene &scene, const Camera &camera, const Grid &grid, double aspect,
                      int columns = 48,
                      double stopAboveTestsPerRay = std::numeric_limits<double>::infinity());

} // namespace prism
