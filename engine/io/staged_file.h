#pragma once
// Write-then-rename: output goes to a hidden temporary file beside the target, which
// replaces the target in one rename(2) (atomic on POSIX) only once it is complete. A process
// stopped by SIGTERM, SIGINT or SIGHUP removes its temporary files (io/temp_file_cleanup.h).
#include <filesystem>

namespace prism {

class StagedFile {
public:
    // Temporary path: "<dir>/.<stem>.tmp-<pid><ext>", keeping the extension so tools that
    // pick a format by name still see it.
    explicit StagedFile(std::filesystem::path target);
    ~StagedFile(); // removes the temporary file unless commit() succeeded
    StagedFile(const StagedFile &) = delete;
    StagedFile &operator=(const StagedFile &) = delete;

    const std::filesystem::path &tempPath() const { return temp_; }
    const std::filesystem::path &target() const { return target_; }

    // Flushes the temporary file to disk, then renames it over the target.
    // Throws prism::Error naming the target; the temporary file is removed either way.
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path temp_;
    bool committed_ = false;
    int watch_ = -1; // removed if a signal stops the process first (io/temp_file_cleanup.h)
};

// Checks, before any work, that `target` can be written the way StagedFile writes it: its
// directory exists and a file can be made there (a probe, made and removed at once), and it is
// not a directory. Throws prism::Error naming the path and why, so that a typo in `-o` fails
// in a moment instead of after a long render.
void checkCanStage(const std::filesystem::path &target);

} // namespace prism
