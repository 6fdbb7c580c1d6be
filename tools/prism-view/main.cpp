// prism-view: fly through a scene in a window, ray traced on the GPU. See --help and
// docs/prism-view.md.
#include <cstdio>
#include <exception>
#include <memory>

#include "core/error.h"
#include "script_driver.h"
#include "view_options.h"
#include "viewer.h"

int main(int argc, char **argv) {
    try {
        prism::ViewOptions options;
        prism::ViewScript script;
        int exitCode = 0;
        if (!prism::parseViewOptions(argc, argv, options, script, exitCode))
            return exitCode;
        std::unique_ptr<prism::ViewDriver> driver = prism::makeViewDriver(script);
        prism::Viewer viewer(options, *driver);
        return viewer.run();
    } catch (const prism::FileError &e) {
        std::fprintf(stderr, "%s\n", e.what()); // already "FILE:LINE: what is wrong"
    } catch (const std::exception &e) {
        std::fprintf(stderr, "prism-view: error: %s\n", e.what());
    }
    return 1;
}
