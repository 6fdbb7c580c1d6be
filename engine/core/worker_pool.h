#pragma once
// Threads that parallelFor keeps between calls. A new thread a call costs ~50 us to start here
// (a 2-core VM), a parked one ~20 us to wake, and a loop of small views calls parallelFor
// every frame (the tile start distances, the readback: docs/benchmarks.md, "A small view's host
// work"). One caller at a time uses the pool; a call made while it is in use (nested in a
// body, or from another thread) gets false and starts threads of its own, as before.
//
// The workers are detached and the pool is never destroyed: the process's exit ends them, so
// nothing waits on a worker at exit. A child made by fork() has none of its parent's threads;
// the pool forgets them there (pthread_atfork), so a parallelFor in the child starts new ones
// instead of waiting for threads that do not exist (Python's multiprocessing forks).
#include <cstddef>
#include <functional>

namespace prism {

// Runs job() on `workers` pool threads and on the calling thread, and returns once every call
// has returned; job must not throw. false (job not run) when the pool is in use.
bool runOnWorkerPool(size_t workers, const std::function<void()> &job);

} // namespace prism
