#pragma once
#include <cstdint>

namespace prism {

// Rays a render traced, counted by the tracer itself (GPU atomics or CPU counters).
struct RayCounts {
    uint64_t primary = 0, shadow = 0, secondary = 0;
    uint64_t total() const { return primary + shadow + secondary; }
};

} // namespace prism
