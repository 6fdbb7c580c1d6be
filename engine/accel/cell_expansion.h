#pragma once
// Growing the adaptive grid's cells over neighbouring space whose primitives they already list
// (the expansion of Pérard-Gayot, Kalojanov & Slusallek 2017): a ray then crosses empty space
// near geometry, and between objects, in few steps. The voxel map is unchanged; only the boxes
// the walk leaves through grow, so boxes overlap afterwards and each voxel's own cell still
// holds it.
#include "accel/grid.h"

namespace prism {

// Rounds over the six faces of every cell (each round tries each face once).
constexpr int kExpansionRounds = 3;

// Expands grid.cellBoxes of an adaptive grid in place. A cell grows across a face only by whole
// neighbouring cells, and only when every primitive of each of them is in its own list (empty
// neighbours always qualify), so every primitive that overlaps the grown box is still listed.
void expandCells(Grid &grid);

} // namespace prism
