// parallelFor runs each index once, passes a body's exception on, and uses no more threads than
// ParallelThreads allows (the thread-count determinism tests rely on that).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/parallel_for.h"

namespace prism {
namespace {

// The threads that ran parallelFor's bodies, over enough slow indices for all to join in.
std::set<std::thread::id> threadsUsed() {
    std::set<std::thread::id> ids;
    std::mutex mutex;
    parallelFor(64, [&](size_t) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        std::lock_guard lock(mutex);
        ids.insert(std::this_thread::get_id());
    });
    return ids;
}

TEST(ParallelFor, RunsEachIndexOnce) {
    std::vector<std::atomic<int>> runs(1000);
    parallelFor(runs.size(), [&](size_t i) { ++runs[i]; });
    for (const std::atomic<int> &r : runs)
        ASSERT_EQ(r, 1);
}

TEST(ParallelFor, RethrowsABodysException) {
    EXPECT_THROW(parallelFor(100,
                             [](size_t i) {
                                 if (i == 37)
                                     throw std::runtime_error("index 37");
                             }),
                 std::runtime_error);
}

TEST(ParallelFor, UsesAtMostTheThreadsAllowed) {
    {
        ParallelThreads limit(1);
        std::set<std::thread::id> ids = threadsUsed();
        ASSERT_EQ(ids.size(), 1u);
        EXPECT_EQ(*ids.begin(), std::this_thread::get_id());
    }
    {
        ParallelThreads limit(3);
        EXPECT_EQ(parallelThreadCount(), 3u);
        std::set<std::thread::id> ids = threadsUsed();
        EXPECT_GE(ids.size(), 2u) << "three threads allowed, more than one used";
        EXPECT_LE(ids.size(), 3u);
    }
    EXPECT_EQ(parallelThreadCount(), std::max(1u, std::thread::hardware_concurrency()))
        << "the limit ends with its scope";
}

} // namespace
} // namespace prism
