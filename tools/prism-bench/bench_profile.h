#pragma once
// prism-bench --profile: runs the profiling tracer beside the timed variants and prints where
// each variant's time goes.
#include <vector>

#include "bench_study.h"
#include "scene/scene.h"

namespace prism {

// Profiles one variant of `scene` (centred, with `grid` built for it) over settings.runs frames
// at each level after a warm-up frame; the context must have been created with shaderClock.
BenchProfile profileVariant(vk::Context &context, const Scene &scene, const Grid &grid,
                            const BenchVariant &variant, const BenchSettings &settings);

// A Markdown table of the results that have a profile.
void printProfileTable(const std::vector<BenchResult> &results);

} // namespace prism
