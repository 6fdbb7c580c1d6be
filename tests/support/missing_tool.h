#pragma once
// What a GoogleTest does when a tool it needs (xvfb-run, Embree) is missing: fail, naming it,
// where the build requires the test tools (PRISM_REQUIRE_TEST_TOOLS, on by default: the README's
// setup installs them all), else skip with the reason. A macro, because both FAIL() and
// GTEST_SKIP() return from the test body they are written in.
#include <gtest/gtest.h>

#ifdef PRISM_REQUIRE_TEST_TOOLS
#define PRISM_MISSING_TEST_TOOL(why)                                                              \
    FAIL() << why                                                                                 \
           << " (tools/scripts/install-deps.sh installs it; configure with "                      \
              "-DPRISM_REQUIRE_TEST_TOOLS=OFF to skip instead)"
#else
#define PRISM_MISSING_TEST_TOOL(why) GTEST_SKIP() << "skipped: " << why
#endif
