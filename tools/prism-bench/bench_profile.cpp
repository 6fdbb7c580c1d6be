#include "bench_profile.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/median.h"
#include "render/ray_tracer.h"

namespace prism {

double PhaseProfile::walksNs() const {
    return nsPerSample[gpu::kPhasePrimaryWalk] + nsPerSample[gpu::kPhaseSecondaryWalk] +
           nsPerSample[gpu::kPhaseShadowWalk];
}

double PhaseProfile::nsOutsidePhases() const {
    return nsPerSample[gpu::kPhaseTotal] - nsPerSample[gpu::kPhaseCamera] - walksNs() -
           nsPerSample[gpu::kPhaseShading] - nsPerSample[gpu::kPhaseStack] -
           nsPerSample[gpu::kPhaseOutput] - nsPerSample[gpu::kPhaseClockReads];
}

namespace {

PhaseProfile profileLevel(vk::Context &context, const Scene &scene, const Grid &grid,
                          const BenchVariant &variant, const BenchSettings &settings,
                          uint32_t level) {
    TracerOptions options = variant.tracer;
    options.maxDepth = settings.maxDepth;
    options.profile = level;
    RayTracer tracer(context, scene, grid, settings.width, settings.height, options);
    tracer.setSeed(settings.seed);
    tracer.renderFrame(scene.camera, settings.samplesPerPixel); // compile, warm caches
    std::array<std::vector<double>, gpu::kProfileSlots> ns;
    std::vector<double> frameMs;
    double samples = double(settings.width) * settings.height * settings.samplesPerPixel;
    for (uint32_t run = 0; run < settings.runs; ++run) {
        FrameResult f = tracer.renderFrame(scene.camera, settings.samplesPerPixel);
        frameMs.push_back(f.gpuMs);
        for (uint32_t p = 0; p < gpu::kProfileSlots; ++p)
            ns[p].push_back(double(f.phaseNs[p]) / samples);
    }
    PhaseProfile profile;
    for (uint32_t p = 0; p < gpu::kProfileSlots; ++p)
        profile.nsPerSample[p] = median(ns[p]);
    profile.frameMs = median(frameMs);
    profile.nsPerFrameSample = profile.frameMs * 1e6 / samples;
    return profile;
}

} // namespace

BenchProfile profileVariant(vk::Context &context, const Scene &scene, const Grid &grid,
                            const BenchVariant &variant, const BenchSettings &settings) {
    return {profileLevel(context, scene, grid, variant, settings, 1),
            profileLevel(context, scene, grid, variant, settings, 2)};
}

void printProfileTable(const std::vector<BenchResult> &results) {
    std::printf("\nWhere the time goes (--profile): in-shader clocks, ns per pixel sample summed "
                "over cores, each phase's cost to its subgroup (shaders/profile.glsl). "
                "\"cores\": total / frame time; \"tests\": share of the walks spent in primitive "
                "loops (level 2); \"slowdown\": profiled frame / plain frame.\n\n");
    std::printf("| scene | variant | camera | primary walk | secondary walks | shadow walks | "
                "shading | stack | output | other | clock reads | total | ns/ray | cores | tests | "
                "slowdown |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const BenchResult &r : results) {
        if (!r.profile)
            continue;
        const PhaseProfile &p = r.profile->phases;
        const PhaseProfile &d = r.profile->detail;
        double total = p.nsPerSample[gpu::kPhaseTotal];
        auto share = [&](double ns) {
            char text[48];
            std::snprintf(text, sizeof text, "%.0f (%.0f%%)", ns,
                          total > 0.0 ? 100.0 * ns / total : 0.0);
            return std::string(text);
        };
        double raysPerSample =
            double(r.rays.total()) / double(std::max<uint64_t>(1, r.rays.primary));
        std::string phases = share(p.nsPerSample[gpu::kPhaseCamera]) + " | " +
                             share(p.nsPerSample[gpu::kPhasePrimaryWalk]) + " | " +
                             share(p.nsPerSample[gpu::kPhaseSecondaryWalk]) + " | " +
                             share(p.nsPerSample[gpu::kPhaseShadowWalk]) + " | " +
                             share(p.nsPerSample[gpu::kPhaseShading]) + " | " +
                             share(p.nsPerSample[gpu::kPhaseStack]) + " | " +
                             share(p.nsPerSample[gpu::kPhaseOutput]) + " | " +
                             share(p.nsOutsidePhases()) + " | " +
                             share(p.nsPerSample[gpu::kPhaseClockReads]);
        double tests = d.walksNs() > 0.0
                           ? 100.0 * d.nsPerSample[gpu::kPhasePrimitiveTests] / d.walksNs()
                           : 0.0;
        std::printf("| %s | %s | %s | %.0f | %.0f | %.2f | %.0f%% | %.2f |\n", r.scene.c_str(),
                    r.variant.c_str(), phases.c_str(), total, total / raysPerSample,
                    p.nsPerFrameSample > 0.0 ? total / p.nsPerFrameSample : 0.0, tests,
                    r.medianMs() > 0.0 ? p.frameMs / r.medianMs() : 0.0);
    }
}

} // namespace prism
