#include "render/lavapipe_threads.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace prism {

uint32_t lavapipeDispatchShares(uint32_t hardwareThreads, const char *override) {
    uint32_t threads = hardwareThreads > 1 ? hardwareThreads : 0;
    if (override && *override) {
        // Mesa's debug_get_num_option reads a whole number; anything else leaves the default.
        uint32_t value = 0;
        const char *end = override + std::strlen(override);
        auto [stop, error] = std::from_chars(override, end, value);
        if (error == std::errc() && stop == end)
            threads = value;
    }
    return std::max(1u, std::min(threads, kLavapipeMaxThreads));
}

uint32_t lavapipeDispatchShares() {
    return lavapipeDispatchShares(std::thread::hardware_concurrency(),
                                  std::getenv("LP_NUM_THREADS"));
}

} // namespace prism
