#pragma once
// prism-scenegen's command line: parses argv, generates, writes the file.

namespace prism::scenegen {

// Returns the process exit status: 0 on success (and for --help), non-zero after printing a
// message for bad usage. Throws prism::Error when generating or writing fails.
int runScenegen(int argc, char **argv);

} // namespace prism::scenegen
