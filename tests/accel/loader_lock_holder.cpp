// A library for loader_lock_test.cpp whose constructor holds the dynamic loader's lock, as
// `dlopen` holds it for a whole load (OpenImageIO's ~260 libraries: ~200 ms as prism-render
// starts), until the test lets it go: it says it is running by writing a byte to the pipe
// named by PRISM_TEST_LOCK_HELD, then waits for a byte on PRISM_TEST_LOCK_RELEASE.
#include <cstdlib>

#include <unistd.h>

namespace {

__attribute__((constructor)) void holdTheLoaderLock() {
    const char *held = std::getenv("PRISM_TEST_LOCK_HELD");
    const char *release = std::getenv("PRISM_TEST_LOCK_RELEASE");
    if (!held || !release)
        return;
    char byte = 1;
    if (write(std::atoi(held), &byte, 1) != 1)
        return;
    (void)!read(std::atoi(release), &byte, 1);
}

} // namespace
