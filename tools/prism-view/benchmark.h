#pragma once
// --benchmark N: a fixed camera path flown for N frames without input, and the one JSON line
// that reports it (the viewer's own number for docs/).
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace prism {

// Frame `frame` of `frames`: the scene's camera swung +-30 degrees about its look point's up
// axis and dollied in by up to 20% and back, so every frame is a new view (no accumulation).
Camera benchmarkCamera(const Camera &start, uint32_t frame, uint32_t frames);

struct BenchmarkReport {
    std::string scene, device, presentMode, grid;
    uint32_t width = 0, height = 0, depth = 0;
    uint32_t warmupFrames = 0;
    std::vector<double> frameMs; // measured frames, host wall clock between frame starts
    uint64_t rays = 0;           // traced in the measured frames
    double warmupMs = 0.0;       // the warm-up frames, with the shader compile (lavapipe
                                 // compiles at the first dispatch)
    // Where the scene shown came from: its load and its grid's build (or the cache's read), and
    // the cache's part in them (prism-render --stats' names).
    double loadMs = 0.0, buildMs = 0.0;
    std::string gridCache = "off"; // "off", "hit" or "miss"
    uint32_t objCacheHits = 0, objCacheMisses = 0;
};

std::string benchmarkJson(const BenchmarkReport &report);

} // namespace prism
