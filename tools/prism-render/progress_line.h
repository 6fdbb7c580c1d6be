#pragma once
// "prism-render: frame 1/3 42%, 3.9 Mrays/s, 12s left, 9.1s elapsed" on stderr, shown only once
// work has taken over a second so that short renders stay silent. On a terminal the line is
// rewritten in place; where stderr is a file or a pipe (a farm's log) only the last state is
// written, once, at the end, so that logs do not fill with carriage returns.
#include <cstdio>
#include <string>

#include <unistd.h>

#include "core/timer.h"

namespace prism {

std::string durationText(double seconds); // "1m05s", "12s", "0.4s" (render_run.cpp)

class ProgressLine {
public:
    explicit ProgressLine(bool enabled) : enabled_(enabled), terminal_(::isatty(2) == 1) {}
    ~ProgressLine() { finish(); }

    // "LABEL NN%, R Mrays/sAFTER, T elapsed": `after` says more of the whole (", 1m20s left");
    // without it, the time left of this label's work is estimated from its fraction so far.
    // The rate is left out where the caller does not know it yet (0).
    void update(const std::string &label, double fraction, const std::string &after = {},
                double mraysPerSecond = 0.0) {
        if (!enabled_)
            return;
        if (label != label_) {
            label_ = label;
            labelTimer_ = Timer();
        }
        double elapsed = timer_.elapsedMs() / 1e3;
        if (elapsed < 1.0)
            return;
        std::string text = label + " " + std::to_string(int(fraction * 100.0)) + "%";
        if (mraysPerSecond > 0.0) {
            char rate[32];
            std::snprintf(rate, sizeof rate, ", %.3g Mrays/s", mraysPerSecond);
            text += rate;
        }
        double labelSeconds = labelTimer_.elapsedMs() / 1e3;
        if (!after.empty())
            text += after;
        else if (fraction > 0.0 && fraction < 1.0 && labelSeconds > 0.5)
            text += ", " + durationText(labelSeconds / fraction * (1.0 - fraction)) + " left";
        text += ", " + durationText(elapsed) + " elapsed";
        last_ = text;
        if (!terminal_)
            return;
        // Blanks over whatever a longer line before left behind.
        size_t pad = text.size() < shownLength_ ? shownLength_ - text.size() : 0;
        std::fprintf(stderr, "\rprism-render: %s%*s", text.c_str(), int(pad), "");
        std::fflush(stderr);
        shownLength_ = text.size();
    }
    void finish() {
        if (!last_.empty()) {
            if (terminal_)
                std::fprintf(stderr, "\n");
            else
                std::fprintf(stderr, "prism-render: %s\n", last_.c_str());
        }
        last_.clear();
        shownLength_ = 0;
    }

private:
    bool enabled_, terminal_;
    std::string label_, last_;
    size_t shownLength_ = 0;
    Timer timer_, labelTimer_;
};

} // namespace prism
