#pragma once
// Runs every variant of every scene, interleaved: each round renders one frame of each variant
// in turn, so slow drift of a shared machine affects all variants alike and their ratios hold.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "accel/walk_counts.h"
#include "bench_variant.h"
#include "core/ray_counts.h"
#include "phase_profile.h"
#include "vk/context.h"

namespace prism {

struct BenchSettings {
    uint32_t width = 1024, height = 768;
    uint32_t samplesPerPixel = 1;
    uint32_t seed = 0; // the sampling seed (RayTracer::setSeed): another set of samples
    uint32_t maxDepth = 5;
    uint32_t runs = 5; // timed frames per variant, after one warm-up frame
    // Also trace each scene's camera and shadow rays with Intel Embree on all cores (the
    // baseline of issue 11), interleaved with the variants' frames: a row named "embree".
    bool embreeBaseline = false;
    // Also run each variant's profiling tracer (in-shader clocks per phase; the context needs
    // the shader clock) after its timed frames: BenchResult::profile.
    bool profile = false;
    // For the studies (docs/studies): keep the scene's file origin instead of moving it to the
    // camera (scene/scene_origin.h), to show what that centring protects against; and, when not
    // empty, write each variant's warm-up frame to imageDir/SCENE_VARIANT.exr.
    bool keepOrigin = false;
    std::string imageDir;
    // Every scene set up first (all in memory at once) and each run's frames taken across all
    // scenes in turn, as across variants: ratios between scenes (the per-ray cost against a
    // scene's size) then hold on a noisy machine as ratios between variants do.
    bool interleaveScenes = false;
};

struct BenchResult {
    std::string scene, variant;
    uint64_t primitives = 0;
    std::string grid;
    uint32_t maxPerCell = 0;
    uint64_t gridBytes = 0;
    uint64_t sceneBytes = 0; // every array on the device, the grid's included
    WalkCounts walk;         // the grid's work per primary ray, counted on the CPU
    double buildMs = 0.0;
    std::vector<double> frameMs; // GPU time of each timed frame (Embree: wall time)
    std::vector<double> wallMs;  // host wall time of each timed frame (FrameResult::wallMs)
    RayCounts rays;              // of one frame
    std::optional<BenchProfile> profile;
    double medianMs() const;
    double medianWallMs() const;
    double mraysPerSecond() const;     // at the median GPU time
    double wallMraysPerSecond() const; // at the median wall time
};

// Results scene by scene in the order given, each scene's variants in order, then Embree's.
std::vector<BenchResult> runStudy(vk::Context &context, const std::vector<std::string> &scenes,
                                  const std::vector<BenchVariant> &variants,
                                  const BenchSettings &settings,
                                  const std::function<void(const std::string &)> &progress);

} // namespace prism
