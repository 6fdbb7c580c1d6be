#pragma once
// `--grid auto`: the regular grid or the adaptive one, by what each costs the tracer on the
// scene camera's primary rays (accel/walk_counts.h). A regular grid suits evenly spread scenes
// and its DDA step is cheap; the adaptive grid wins where one grid crowds the primitives the
// camera sees into few cells (a small object in a large scene), but each of its steps costs
// more (a voxel-map lookup and a box), and its build is slower.
#include <functional>

#include "accel/grid.h"
#include "accel/walk_counts.h"
#include "scene/scene.h"

namespace prism {

// The tracer's work per ray in primitive tests: a test costs 1, a DDA step kRegularStepCost and
// an adaptive step kAdaptiveStepCost. Fitted to lavapipe (docs/benchmarks.md, "Choosing the
// grid"): with the adaptive grid `scene` visits 1.7 cells and makes 2.1 tests a primary ray
// against the regular grid's 6.1 and 2.6 and traces 0.77x the time; `bunny` 1.5 and 2.7 against
// 5.0 and 3.9, and traces the same; `cornell` 1.4 and 8.7 against 2.0 and 5.3, 1.24x.
constexpr double kRegularStepCost = 1.0;
constexpr double kAdaptiveStepCost = 3.0;
// Below this cost per ray on the regular grid the adaptive one is not built: it cannot save
// enough (it still takes a step and a test a ray) to pay for its build.
constexpr double kConsiderAdaptiveCost = 8.0;
// The adaptive grid is chosen only when it is estimated at least this much cheaper.
constexpr double kAdaptiveMargin = 0.9;

// From this many finite primitives the adaptive grid is built and counted first: its walks'
// nearest hits give lower bounds on the regular grid's cost (walk_counts.h, lowerBoundWalks),
// and where those already settle the choice the regular grid is never built (at a million
// triangles its build and count took 130-200 ms, at four million 1.2 s). Below it, the regular
// grid is built first, as its low cost often settles the choice without the adaptive build.
constexpr uint64_t kAdaptiveFirstFrom = 100'000;

// Builds the regular grid with build(Regular); where its cost calls for it, the adaptive one with
// build(Adaptive), and returns the cheaper, with Grid::choice saying why. For big scenes
// (kAdaptiveFirstFrom) the adaptive grid comes first, and the regular one is built only where
// its lower bounds (regularLayout(): its box and resolution, no cells) do not settle the
// choice; the choice is the same either way.
Grid chooseGrid(const Scene &scene, const std::function<Grid(GridOptions::Mode)> &build,
                const std::function<Grid()> &regularLayout);

} // namespace prism
