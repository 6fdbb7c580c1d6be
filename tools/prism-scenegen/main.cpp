// prism-scenegen: writes the generated benchmark scenes. See --help.
#include <cstdio>
#include <exception>

#include "cli.h"

int main(int argc, char **argv) {
    try {
        return prism::scenegen::runScenegen(argc, argv);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "prism-scenegen: error: %s\n", e.what());
    }
    return 1;
}
