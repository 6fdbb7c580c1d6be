#pragma once
// Intel Embree 3 as the yardstick for Prism (issues 8 and 11): its BVH build over a scene's
// finite primitives and planes, and a frame of the same camera rays and shadow rays Prism
// traces at depth 1, on all cores, in 8-wide packets. Built only where Debian's libembree-dev
// is found (embreeAvailable() says which); nothing else in Prism depends on it.
#include <cstdint>
#include <memory>

#include "core/ray_counts.h"
#include "scene/scene.h"

namespace prism {

bool embreeAvailable();

struct EmbreeBuild {
    double setupMs = 0.0;  // device, scene and geometry buffers
    double commitMs = 0.0; // rtcCommitScene: the BVH build itself, on all cores
};

struct EmbreeFrame {
    double ms = 0.0; // wall time of the whole frame
    RayCounts rays;  // primary and shadow
};

// Triangles as RTC_GEOMETRY_TYPE_TRIANGLE, spheres as RTC_GEOMETRY_TYPE_SPHERE_POINT, each
// infinite plane as a quad 10^4 times the scene's size, one geometry each, default (medium)
// build quality. Throws prism::Error where Embree is not available or fails.
class EmbreeBaseline {
public:
    EmbreeBaseline(const Scene &scene, uint32_t width, uint32_t height);
    ~EmbreeBaseline();
    EmbreeBaseline(const EmbreeBaseline &) = delete;
    EmbreeBaseline &operator=(const EmbreeBaseline &) = delete;

    const EmbreeBuild &build() const;
    // One camera ray through each pixel centre (the scene format's camera model, as Prism's
    // reference), and from each hit one shadow ray to each light in front of the surface:
    // Prism's rays at depth 1 and one sample per pixel.
    EmbreeFrame traceFrame();

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace prism
