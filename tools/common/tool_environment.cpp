#include "tool_environment.h"

#include <cstdlib>

namespace prism {

bool validationWanted(bool requested) {
#ifdef PRISM_DEFAULT_VALIDATION
    requested = true;
#endif
    const char *env = std::getenv("PRISM_VALIDATION");
    return requested || (env && std::string(env) == "1");
}

std::string commandLineText(int argc, char **argv) {
    std::string text;
    for (int i = 0; i < argc; ++i) {
        if (i > 0)
            text += ' ';
        text += argv[i];
    }
    return text;
}

} // namespace prism
