#pragma once
// Temporary files that a stop by signal removes. An image is written to a hidden temporary file
// and renamed over its target (io/staged_file.h), so a killed render never leaves a partial
// image under the target's name; but a process ended by SIGTERM (Slurm's scancel, a farm
// manager's timeout), SIGINT (Ctrl-C) or SIGHUP runs no destructors, and its half-written
// temporary file would stay. Files watched here are unlinked by the signal's handler first,
// then the signal ends the process as it would have (the exit status says which signal).
#include <filesystem>

namespace prism {

// Watches `path` until unwatchTempFile(slot). Installs the handlers on first use, for each of
// the three signals whose handling is still the default (a program's own handler is kept).
// Returns the slot, or -1 when every slot is taken (that file then stays after such a stop).
int watchTempFile(const std::filesystem::path &path);
void unwatchTempFile(int slot);

} // namespace prism
