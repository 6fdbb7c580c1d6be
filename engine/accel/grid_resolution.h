#pragma once
// How many cells a grid gets along each axis.
#include <cstdint>

#include <glm/glm.hpp>

namespace prism {

// Largest per-axis resolution and total cell count Prism builds (the cell offsets of a
// 256^3 grid already take 64 MiB of GPU memory).
constexpr int kMaxGridAxisCells = 1024;
constexpr uint64_t kMaxGridCells = uint64_t(1) << 24;

// Cells ~ density * primitiveCount, cubic cells where the bounds allow (so the grid's aspect
// follows the scene's), at least one cell per axis. An axis thinner than one cell gets a single
// cell and the others share the budget (a flat mesh gets a 2D grid, not a wasted 3D one).
glm::ivec3 chooseResolution(const glm::dvec3 &extent, uint64_t primitiveCount, double density);

} // namespace prism
