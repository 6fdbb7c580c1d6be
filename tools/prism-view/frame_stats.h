#pragma once
// What the overlay shows about speed: frames per second, milliseconds per frame and Mrays/s,
// each averaged over the last half second so the numbers can be read.
#include <cstdint>

#include "core/timer.h"

namespace prism {

class FrameStats {
public:
    // One displayed frame took `ms` (host wall clock, frame start to frame start).
    void addFrame(double ms);
    // The GPU finished tracing `rays` more rays (counted by the tracer).
    void addRays(uint64_t rays) { windowRays_ += rays; }

    double fps() const { return fps_; }
    double msPerFrame() const { return msPerFrame_; }
    double mraysPerSecond() const { return mraysPerSecond_; }

private:
    double windowMs_ = 0.0;
    uint32_t windowFrames_ = 0;
    uint64_t windowRays_ = 0;
    double fps_ = 0.0, msPerFrame_ = 0.0, mraysPerSecond_ = 0.0;
};

} // namespace prism
