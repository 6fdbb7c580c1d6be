#pragma once
// What a soak run counts, and the one line that reports it at the end. tools/scripts/soak.sh
// reads that line, so its keys are an interface: add keys, do not rename them.
#include <cstdint>
#include <string>

namespace prism {

struct SoakReport {
    uint32_t frames = 0;
    double seconds = 0.0;
    uint32_t swapchainRebuilds = 0;
    uint32_t resizes = 0, reloads = 0, toggles = 0; // asked for by the script
    uint32_t errors = 0; // reloads and toggles that failed (the last good state stayed)
    // RSS is compared at the ends of periods (soakPeriodFrames), where the script is in the
    // same state each time, so what it allocates and frees within a period does not count.
    uint32_t periodFrames = 0;
    uint32_t warmupFrames = 0; // the period end that ended the warm-up; 0: the run ended first
    long rssStartKiB = 0;      // before the first frame
    long rssWarmKiB = -1;      // at the end of the warm-up; -1: the run ended first
    long rssEndKiB = -1;       // at the last period end after the warm-up's; -1: there was none
    long rssPeakKiB = -1;      // the most seen after the warm-up (period ends, reports, exit)
    long rssExitKiB = 0;       // when the loop ended
    uint32_t validationMessages = 0;
};

// "prism-view: soak frames=... seconds=... ..." (key=value, one line, no newline).
std::string soakSummaryLine(const SoakReport &report);

// This process's resident set size in KiB, from /proc/self/statm.
long residentKiB();

} // namespace prism
