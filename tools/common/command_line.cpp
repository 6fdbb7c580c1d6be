#include "command_line.h"

#include <cstdio>

#include "core/error.h"

namespace prism {

std::optional<int> parseCommandLine(const std::string &tool, CLI::App &app, int argc, char **argv,
                                    const std::function<void()> &check) {
    std::string problem;
    try {
        app.parse(argc, argv);
        if (check)
            check();
        return std::nullopt;
    } catch (const CLI::ParseError &e) {
        if (e.get_exit_code() == 0) // --help, --version: CLI11 prints them
            return app.exit(e);
        problem = e.what();
    } catch (const Error &e) {
        problem = e.what();
    }
    std::fprintf(stderr, "%s: error: %s\nRun %s --help for the options.\n", tool.c_str(),
                 problem.c_str(), tool.c_str());
    return kExitUsage;
}

} // namespace prism
