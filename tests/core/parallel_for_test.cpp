// parallelFor runs each index once, passes a body's exception on, and uses no more threads than
// ParallelThreads allows (the thread-count determinism tests rely on that). Its kept threads
// (core/worker_pool.h) serve one call at a time: calls nested in a body, from several threads
// at once, and in a forked child all finish.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

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

// In blocks: every index once, also where the count is not a multiple of the block, or 0.
TEST(ParallelFor, InBlocksRunsEachIndexOnce) {
    for (size_t count : {0, 1, 999, 1000, 1001}) {
        std::vector<std::atomic<int>> runs(count);
        parallelForInBlocks(count, 100, [&](size_t i) { ++runs.at(i); });
        for (const std::atomic<int> &r : runs)
            ASSERT_EQ(r, 1) << count;
    }
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

// A limit for one thread's loops leaves the other threads' as they were.
TEST(ParallelFor, AThreadsOwnLimitIsItsAlone) {
    ParallelThreads limit(3);
    {
        ParallelThreadsHere alone(1);
        std::set<std::thread::id> ids = threadsUsed();
        ASSERT_EQ(ids.size(), 1u);
        EXPECT_EQ(*ids.begin(), std::this_thread::get_id());
        unsigned elsewhere = 0;
        std::thread([&] { elsewhere = parallelThreadCount(); }).join();
        EXPECT_EQ(elsewhere, 3u);
    }
    EXPECT_EQ(parallelThreadCount(), 3u) << "the thread's limit ends with its scope";
}

// The same threads serve call after call: the pool keeps them.
TEST(ParallelFor, KeepsItsThreadsBetweenCalls) {
    ParallelThreads limit(2);
    std::set<std::thread::id> first = threadsUsed(), second = threadsUsed();
    first.insert(second.begin(), second.end());
    EXPECT_LE(first.size(), 2u) << "a call's helper is the last call's";
}

// A body that calls parallelFor, and calls from several threads at once, while the pool is in
// use: each runs every index once (on threads of its own) and none waits for ever.
TEST(ParallelFor, NestedAndConcurrentCallsFinish) {
    std::vector<std::atomic<int>> runs(64 * 64);
    parallelFor(64, [&](size_t i) { parallelFor(64, [&](size_t j) { ++runs[i * 64 + j]; }); });
    for (const std::atomic<int> &r : runs)
        ASSERT_EQ(r, 1);
    std::vector<std::atomic<int>> counts(4 * 1000);
    std::vector<std::thread> callers;
    for (size_t c = 0; c < 4; ++c)
        callers.emplace_back([&, c] {
            for (int round = 0; round < 20; ++round)
                parallelFor(50, [&](size_t i) { ++counts[c * 1000 + size_t(round) * 50 + i]; });
        });
    for (std::thread &t : callers)
        t.join();
    for (const std::atomic<int> &r : counts)
        ASSERT_EQ(r, 1);
}

// A child forked after the pool has threads (Python's multiprocessing does that) has none of
// them: its parallelFor must start its own and finish, not wait for the parent's.
TEST(ParallelFor, FinishesInAForkedChild) {
    threadsUsed(); // the pool has its threads now
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::atomic<int> sum{0};
        parallelFor(1000, [&](size_t i) { sum += int(i); });
        _exit(sum == 999 * 1000 / 2 ? 0 : 1);
    }
    int status = 0;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            FAIL() << "the forked child's parallelFor did not finish in 20 s";
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the child's parallelFor ran each index once";
}

} // namespace
} // namespace prism
