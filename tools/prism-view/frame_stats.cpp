#include "frame_stats.h"

namespace prism {

void FrameStats::addFrame(double ms) {
    windowMs_ += ms;
    windowFrames_ += 1;
    if (windowMs_ < 500.0)
        return;
    fps_ = 1000.0 * windowFrames_ / windowMs_;
    msPerFrame_ = windowMs_ / windowFrames_;
    mraysPerSecond_ = double(windowRays_) / (windowMs_ * 1e3);
    windowMs_ = 0.0;
    windowFrames_ = 0;
    windowRays_ = 0;
}

} // namespace prism
