#pragma once
// What prism-bench --profile measures for one variant: the in-shader clocks of the profiling
// tracer (shaders/profile.glsl) as nanoseconds per pixel sample for each phase.
#include <array>

#include "shared/profile_phases.h"

namespace prism {

struct PhaseProfile {
    // Median over the profiled frames of each phase's nanoseconds per pixel sample (the
    // subgroups' time, summed over cores), slots as in shared/profile_phases.h.
    std::array<double, gpu::kProfileSlots> nsPerSample{};
    double frameMs = 0.0;           // median GPU time of a profiled frame
    double nsPerFrameSample = 0.0;  // frameMs per pixel sample, in ns: total / this = cores busy
    double walksNs() const;         // primary + secondary + shadow walks
    double nsOutsidePhases() const; // the total less every phase above
};

struct BenchProfile {
    PhaseProfile phases; // level 1: clocks around the phases only
    PhaseProfile detail; // level 2: also around each cell's primitive loop
};

} // namespace prism
