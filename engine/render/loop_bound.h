#pragma once
// A static upper bound on the loop iterations one tracer invocation can run, as lavapipe
// counts them (every iteration of every loop, per 8-wide SIMD group). Where the bound is below
// lavapipe's silent cut-off, the shader's own iteration counting is compiled out: the scene
// provably cannot hit the limit, and pays nothing for the check.
#include <cstdint>

#include "accel/grid.h"
#include "render/tracer_features.h"
#include "scene/scene.h"

namespace prism {

// Iterations of one closest-hit or occlusion query, at most: the plane loop, DDA steps (a ray
// crosses at most res.x + res.y + res.z cells) and the primitive tests in the fullest cells.
uint64_t traversalIterationBound(const Scene &scene, const Grid &grid);

// Iterations of one invocation (one pixel sample) at most: every ray of the ray tree (up to
// 1 + c + c^2 + ... with c children per hit), each with its traversal and its light loop.
// Each term bounds every lane, so it also bounds a SIMD group that runs loops in lockstep.
uint64_t invocationIterationBound(const Scene &scene, const Grid &grid,
                                  const TracerFeatures &features);

} // namespace prism
