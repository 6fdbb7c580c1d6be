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

    // "LABEL NN%AFTER": `after` says more of the whole (", 1m20s left").
    void update(const std::string &label, double fraction, const std::string &after = {}) {
        if (!enabled_ || timer_.elapsedMs() < 1000.0)
            return;
        std::string text = label + " " + std::to_string(int(fraction * 100.0)) + "%" + after;
        // Blanks over whatever a longer line before left behind.
        size_t pad = text.size() < shownLength_ ? shownLength_ - text.size() : 0;
        std::fprintf(stderr, "\rprism-render: %s%*s", text.c_str(), int(pad), "");
        std::fflush(stderr);
        shownLength_ = text.size();
        shown_ = true;
    }
    void finish() {
        if (shown_)
            std::fprintf(stderr, "\n");
        shown_ = false;
        shownLength_ = 0;
    }

private:
    bool enabled_;
    bool shown_ = false;
    size_t shownLength_ = 0;
    Timer timer_;
};

} // namespace prism
