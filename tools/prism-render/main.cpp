// prism-render: a scene file in, an EXR or PNG out. See --help.
#include <cstdio>
#include <exception>

#include "core/error.h"
#include "render_options.h"
#include "render_run.h"

int main(int argc, char **argv) {
    try {
        prism::RenderOptions options;
        int exitCode = 0;
        if (!prism::parseRenderOptions(argc, argv, options, exitCode))
            return exitCode;
        prism::runRender(options);
        return 0;
    } catch (const prism::FileError &e) {
        std::fprintf(stderr, "%s\n", e.what()); // already "FILE:LINE: what is wrong"
    } catch (const std::exception &e) {
        std::fprintf(stderr, "prism-render: error: %s\n", e.what());
    }
    return 1;
}
