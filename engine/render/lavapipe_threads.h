#pragma once
// How many threads lavapipe splits a compute dispatch among, as Mesa decides it (llvmpipe's
// lp_screen.c: one per CPU when there are two or more, else none beside the caller;
// LP_NUM_THREADS overrides; at most LP_MAX_THREADS, 16 in Mesa 22). The tile list orders its
// rows for that many contiguous shares (render/traced_tiles.h, spreadRowOrder). Should Mesa
// decide otherwise, the order is still balanced for the count given, only less so for others.
#include <cstdint>

namespace prism {

constexpr uint32_t kLavapipeMaxThreads = 16;

// `hardwareThreads`: the CPUs Mesa counts; `override`: LP_NUM_THREADS's text, or null.
// Returns the shares of a dispatch (1 when lavapipe runs it on one thread).
uint32_t lavapipeDispatchShares(uint32_t hardwareThreads, const char *override);
// The same for this process (std::thread::hardware_concurrency, the environment).
uint32_t lavapipeDispatchShares();

} // namespace prism
