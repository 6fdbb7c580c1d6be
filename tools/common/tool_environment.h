#pragma once
// What every Prism tool reads from its environment the same way.
#include <string>

namespace prism {

// Validation layers: on when the user asked (--validation), in builds configured with
// PRISM_VALIDATION (the debug preset), or with PRISM_VALIDATION=1 in the environment.
bool validationWanted(bool requested);

// The command line as one string, for image metadata.
std::string commandLineText(int argc, char **argv);

} // namespace prism
