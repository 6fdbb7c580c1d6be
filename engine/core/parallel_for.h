#pragma once
// Runs body(i) for every i in [0, count) on all cores. Each index runs exactly once; which
// thread runs it varies, so a body must write only what index i owns for the result to be the
// same on every run. The first exception a body throws is rethrown here, after every thread
// has stopped.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "core/worker_pool.h"

namespace prism {

// The threads parallelFor may use; 0 means one per core. Set through ParallelThreads.
inline std::atomic<unsigned> &parallelThreadLimit() {
    static std::atomic<unsigned> limit{0};
    return limit;
}

// A limit for the calling thread's loops alone (0: none); set through ParallelThreadsHere.
inline unsigned &threadParallelLimit() {
    thread_local unsigned limit = 0;
    return limit;
}

inline unsigned parallelThreadCount() {
    if (unsigned here = threadParallelLimit(); here > 0)
        return here;
    unsigned limit = parallelThreadLimit();
    return limit > 0 ? limit : std::max(1u, std::thread::hardware_concurrency());
}

// Limits parallelFor to `threads` threads while it lives (0: one per core), so that tests can
// hold a build to the same result at every thread count and benchmarks can measure scaling.
class ParallelThreads {
public:
    explicit ParallelThreads(unsigned threads)
        : previous_(parallelThreadLimit().exchange(threads)) {}
    ~ParallelThreads() { parallelThreadLimit() = previous_; }
    ParallelThreads(const ParallelThreads &) = delete;
    ParallelThreads &operator=(const ParallelThreads &) = delete;

private:
    unsigned previous_;
};

// Limits the parallelFor loops the calling thread starts to `threads` while it lives, other
// threads' loops as they were: for work that shares the cores with another job of its own.
class ParallelThreadsHere {
public:
    explicit ParallelThreadsHere(unsigned threads)
        : previous_(std::exchange(threadParallelLimit(), threads)) {}
    ~ParallelThreadsHere() { threadParallelLimit() = previous_; }
    ParallelThreadsHere(const ParallelThreadsHere &) = delete;
    ParallelThreadsHere &operator=(const ParallelThreadsHere &) = delete;

private:
    unsigned previous_;
};

template <typename Body> void parallelFor(size_t count, Body body) {
    size_t threads = std::min<size_t>(count, parallelThreadCount());
    if (threads <= 1) {
        for (size_t i = 0; i < count; ++i)
            body(i);
        return;
    }
    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex errorMutex;
    auto work = [&] {
        for (size_t i = next++; i < count && !failed; i = next++) {
            try {
                body(i);
            } catch (...) {
                std::lock_guard lock(errorMutex);
                if (!error)
                    error = std::current_exception();
                failed = true;
            }
        }
    };
    // The pool's parked threads where it is free (core/worker_pool.h), else threads of its own.
    if (!runOnWorkerPool(threads - 1, work)) {
        std::vector<std::thread> own;
        for (size_t t = 1; t < threads; ++t)
            own.emplace_back(work);
        work();
        for (std::thread &t : own)
            t.join();
    }
    if (error)
        std::rethrow_exception(error);
}

// Starts the threads parallelFor keeps, now rather than at its first call: a program calls it
// first thing, so that no loop later starts a thread while another thread is loading shared
// libraries (a thread's start waits for the dynamic loader's lock, which `dlopen` holds for a
// whole load: 70-200 ms while prism-render loads OpenImageIO's ~260 libraries).
inline void startParallelThreads() {
    runOnWorkerPool(parallelThreadCount() - 1, [] {});
}

// body(i) for every i in [0, count), handed out `block` indices at a time: for loops whose
// bodies are too small to be scheduled one by one (writing a big array, each element its own).
template <typename Body> void parallelForInBlocks(size_t count, size_t block, Body body) {
    parallelFor((count + block - 1) / block, [&](size_t b) {
        for (size_t i = b * block, end = std::min(count, (b + 1) * block); i < end; ++i)
            body(i);
    });
}

} // namespace prism
