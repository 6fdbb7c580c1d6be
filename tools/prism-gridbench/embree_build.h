#pragma once
// Intel Embree's BVH build over a scene's finite primitives, timed: the yardstick for Prism's grid
// builds (issue 8). Built only where Debian's libembree-dev is found; elsewhere embreeAvailable()
// is false and timeEmbreeBuild is never called.
#include "scene/scene.h"

namespace prism {

struct EmbreeBuild {
    double setupMs = 0.0;  // device, scene and geometry buffers
    double commitMs = 0.0; // rtcCommitScene: the BVH build itself, on all cores
};

bool embreeAvailable();
// Triangles as RTC_GEOMETRY_TYPE_TRIANGLE, spheres as RTC_GEOMETRY_TYPE_SPHERE_POINT, one
// geometry each, default (medium) build quality, as Embree's own viewers build static scenes.
EmbreeBuild timeEmbreeBuild(const Scene &scene);

} // namespace prism
