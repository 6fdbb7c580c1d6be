#include "soak_report.h"

#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace prism {

std::string soakSummaryLine(const SoakReport &r) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "prism-view: soak frames=%u seconds=%.1f swapchain_rebuilds=%u resizes=%u "
                  "reloads=%u toggles=%u errors=%u period_frames=%u warmup_frames=%u "
                  "rss_kib_start=%ld rss_kib_warm=%ld rss_kib_end=%ld rss_kib_peak=%ld "
                  "rss_kib_exit=%ld validation_messages=%u",
                  r.frames, r.seconds, r.swapchainRebuilds, r.resizes, r.reloads, r.toggles,
                  r.errors, r.periodFrames, r.warmupFrames, r.rssStartKiB, r.rssWarmKiB,
                  r.rssEndKiB, r.rssPeakKiB, r.rssExitKiB, r.validationMessages);
    return line;
}

long residentKiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

} // namespace prism
