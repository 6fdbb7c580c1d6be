#pragma once
// "prism-render: frame 1/3 42%" on stderr, shown only once work has taken over a second so
// short renders stay silent.
#include <cstdio>
#include <string>

#include "core/timer.h"

namespace prism {

class ProgressLine {
public:
    explicit ProgressLine(bool enabled) : enabled_(enabled) {}
    ~ProgressLine() { finish(); }

    void update(const std::string &label, double fraction) {
        if (!enabled_ || timer_.elapsedMs() < 1000.0)
            return;
        std::fprintf(stderr, "\rprism-render: %s %3d%%", label.c_str(), int(fraction * 100.0));
        std::fflush(stderr);
        shown_ = true;
    }
    void finish() {
        if (shown_)
            std::fprintf(stderr, "\n");
        shown_ = false;
    }

private:
    bool enabled_;
    bool shown_ = false;
    Timer timer_;
};

} // namespace prism
