// prism-view: fly through a scene in a window, ray traced on the GPU. See --help and
// docs/prism-view.md.
#include <cstdio>
#include <exception>

#include "core/error.h"
#include "view_options.h"
#include "viewer.h"

int main(int argc, char **argv) {
    try {
        prism::ViewOptions options;
        int exitCode = 0;
        if (!prism::parseViewOptions(argc, argv, options, exitCode))
            return exitCode;
        prism::Viewer viewer(options);
        return viewer.run();
    } catch (const prism::FileError &e) {
        std::fprintf(stderr, "%s\n", e.what()); // already "FILE:LINE: what is wrong"
    } catch (const std::exception &e) {
        std::fprintf(stderr, "prism-view: error: %s\n", e.what());
    }
    return 1;
}
