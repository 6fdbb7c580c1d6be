#pragma once
// The command-line conventions every Prism tool shares (issue 35): --help and --version print
// and exit 0; a usage error (an unknown option, a bad or missing value, options that do not go
// together) prints "TOOL: error: WHAT" and where to find the options on stderr and exits 2, the
// POSIX status for bad usage; a failure of the work itself exits 1 (each tool's main).
#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace prism {

constexpr int kExitUsage = 2;

// Parses argv into `app`, then runs `check`: the tool's own checks of the values given, which
// throw prism::Error for a bad value or combination. Returns the status to exit with (0 after
// --help or --version, kExitUsage after a usage error), or nothing when the tool should go on.
std::optional<int> parseCommandLine(const std::string &tool, CLI::App &app, int argc, char **argv,
                                    const std::function<void()> &check = {});

} // namespace prism
