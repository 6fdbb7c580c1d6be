// The adaptive build never waits for the dynamic loader's lock. prism-render loads OpenImageIO
// on a thread of its own while the scene loads and its grid builds, and `dlopen` holds the
// loader's lock for the whole load (~200 ms); a build whose threads took it (a thread_local
// with a destructor registers that destructor under it at each thread's first use) waited out
// the load: 200 ms of a 100k-triangle build that takes 20 (benchmarks.md, thirtieth session).
//
// Here a library's constructor holds the lock (loader_lock_holder.cpp) while a child process
// builds grids, full and lean; a build that waits for the lock never ends, and the child is
// killed after a minute. A child, so that the threads are new, as in a fresh prism-render (a
// thread that took the lock once, in an earlier test, would not take it again).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include <dlfcn.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "accel/grid.h"
#include "core/parallel_for.h"
#include "grid_test_scenes.h"

namespace prism {
namespace {

// In the child: builds while the lock is held; 0 when every build made its cells.
int buildWhileTheLockIsHeld(const Scene &scene) {
    startParallelThreads(); // as prism-render does before anything loads a library
    int held[2], release[2];
    if (pipe(held) != 0 || pipe(release) != 0)
        return 3;
    setenv("PRISM_TEST_LOCK_HELD", std::to_string(held[1]).c_str(), 1);
    setenv("PRISM_TEST_LOCK_RELEASE", std::to_string(release[0]).c_str(), 1);
    std::thread loader([] { dlopen(PRISM_LOADER_LOCK_HOLDER, RTLD_NOW | RTLD_LOCAL); });
    char byte = 0;
    if (read(held[0], &byte, 1) != 1)
        return 4;
    bool built = true;
    for (const char *effort : {"full", "lean"}) {
        GridOptions options = parseGridOption("adaptive");
        if (std::string(effort) == "lean")
            options.effort = GridOptions::Effort::Lean;
        built = built && !buildGrid(scene, options).cellPrimitives.empty();
    }
    if (write(release[1], &byte, 1) != 1)
        return 5;
    loader.join();
    return built ? 0 : 2;
}

TEST(LoaderLock, TheAdaptiveBuildNeverWaitsForIt) {
    Scene scene = test::clusterInARoom(48, 30'000, 200);
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0)
        _exit(buildWhileTheLockIsHeld(scene));
    int status = 0;
    auto start = std::chrono::steady_clock::now();
    while (waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(60)) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            FAIL() << "the build waited for the dynamic loader's lock";
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

} // namespace
} // namespace prism
