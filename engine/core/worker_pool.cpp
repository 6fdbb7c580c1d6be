#include "core/worker_pool.h"

#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>
#include <vector>

namespace prism {
namespace {

constexpr size_t kMaxWorkers = 256;

struct Pool {
    std::atomic<bool> inUse{false};
    std::mutex mutex; // guards what follows
    // One for each worker: a job wakes only the workers it wants (a few parts on many cores).
    std::vector<std::unique_ptr<std::condition_variable>> wakes;
    std::condition_variable done;
    size_t started = 0;      // workers made (detached), numbered 0 .. started - 1
    uint64_t generation = 0; // one more for each job handed out
    size_t wanted = 0;       // the workers 0 .. wanted - 1 take the current job
    size_t running = 0;      // of those, the ones not finished with it
    const std::function<void()> *job = nullptr;
};

// Never destroyed (worker_pool.h); made in place, so that a forked child can make it anew.
alignas(Pool) unsigned char poolStorage[sizeof(Pool)];
Pool *pool = nullptr;
std::once_flag poolMade;

// In a forked child: the parent's workers do not exist here, and a mutex one of them held is
// held for ever. A new pool, with no workers, in the same place.
void forgetWorkersInChild() {
    pool = new (poolStorage) Pool;
}

Pool &workerPool() {
    std::call_once(poolMade, [] {
        pool = new (poolStorage) Pool;
        pthread_atfork(nullptr, nullptr, forgetWorkersInChild);
    });
    return *pool;
}

void workerLoop(Pool &p, size_t index, uint64_t seen, std::condition_variable &wake) {
    std::unique_lock lock(p.mutex);
    for (;;) {
        wake.wait(lock, [&] { return p.generation != seen; });
        seen = p.generation;
        if (index >= p.wanted)
            continue;
        const std::function<void()> &job = *p.job;
        lock.unlock();
        job();
        lock.lock();
        if (--p.running == 0)
            p.done.notify_one();
    }
}

} // namespace

bool runOnWorkerPool(size_t workers, const std::function<void()> &job) {
    if (workers == 0) {
        job();
        return true;
    }
    Pool &p = workerPool();
    bool idle = false;
    if (workers > kMaxWorkers || !p.inUse.compare_exchange_strong(idle, true))
        return false;
    {
        std::lock_guard lock(p.mutex);
        try {
            for (; p.started < workers; ++p.started) {
                if (p.wakes.size() == p.started)
                    p.wakes.push_back(std::make_unique<std::condition_variable>());
                std::thread(workerLoop, std::ref(p), p.started, p.generation,
                            std::ref(*p.wakes[p.started]))
                    .detach();
            }
        } catch (const std::system_error &) {
            // No more threads to be had: the job runs on those there are.
        }
        p.wanted = std::min(workers, p.started);
        p.running = p.wanted;
        p.job = &job;
        ++p.generation;
    }
    for (size_t w = 0; w < p.wanted; ++w)
        p.wakes[w]->notify_one();
    job();
    {
        std::unique_lock lock(p.mutex);
        p.done.wait(lock, [&] { return p.running == 0; });
        p.job = nullptr;
    }
    p.inUse = false;
    return true;
}

} // namespace prism
