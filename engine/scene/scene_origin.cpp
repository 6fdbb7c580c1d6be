#include "scene/scene_origin.h"

#include <algorithm>
#include <cfloat>
#include <vector>

#include "core/parallel_for.h"

namespace prism {

namespace {

// Everything moveOrigin moves but the scene's triangles, which each caller moves its own way.
void moveAllButTriangles(Scene &scene, glm::dvec3 point) {
    scene.origin += point;
    scene.camera.eye -= point;
    scene.camera.look -= point;
    for (CameraKey &k : scene.cameraAnimation.keys) {
        k.camera.eye -= point;
        k.camera.look -= point;
    }
    if (scene.cameraAnimation.turntable)
        scene.cameraAnimation.turntable->center -= point;
    for (Light &l : scene.lights)
        l.position -= point;
    for (Sphere &s : scene.spheres)
        s.center -= point;
    for (Plane &p : scene.planes)
        p.point -= point;
    for (Instance &i : scene.instances) // prototypes live in their own space
        i.translation -= point;
    for (PlacementTrack &track : scene.placementTracks)
        track.first.translation -= point;
}

// x rounded to a float and back. The empty `asm` takes the float in a register, where no fold
// sees through it: GCC 12's SLP vectoriser, given double(float(x)) for a vector's three
// components inline, drops the pair of conversions at -O2 and -O3 (1000000.3 - 1000000.25
// stayed 0.050000000047 instead of the float 0.050000000745; in a loop over triangles only z
// was rounded). A call per component (`noinline`) was correct too, but took 34 ms for 1M
// triangles; this stays inline, and the loop vectorises.
inline double roundedToFloat(double x) {
    float f = float(x);
#if defined(__x86_64__) || defined(__i386__)
    asm("" : "+x"(f)); // an SSE register
#elif defined(__aarch64__)
    asm("" : "+w"(f)); // a SIMD and floating-point register
#else
    asm("" : "+m"(f)); // through memory: slower, as sure
#endif
    return double(f);
}

glm::dvec3 asFloat(const glm::dvec3 &p) {
    return {roundedToFloat(p.x), roundedToFloat(p.y), roundedToFloat(p.z)};
}

// The scene's triangles moved by -point, and rounded to floats when `round`: in one pass, on
// every core (1M triangles are 80 MB, read and written once).
void moveTriangles(std::vector<Triangle> &triangles, glm::dvec3 point, bool round) {
    parallelForInBlocks(triangles.size(), 16384, [&](size_t i) {
        for (glm::dvec3 &p : triangles[i].p)
            p = round ? asFloat(p - point) : p - point;
    });
}

} // namespace

void moveOrigin(Scene &scene, glm::dvec3 point) {
    moveAllButTriangles(scene, point);
    moveTriangles(scene.triangles, point, false);
}

void roundToFloat(Instance &instance) {
    instance.translation = asFloat(instance.translation);
    instance.scale = roundedToFloat(instance.scale);
    for (int c = 0; c < 3; ++c)
        instance.rotation[c] = asFloat(instance.rotation[c]);
}

void centerOn(Scene &scene, glm::dvec3 point) {
    moveAllButTriangles(scene, point);
    moveTriangles(scene.triangles, point, true); // p - point, rounded: as moveOrigin, then round
    scene.camera.eye = asFloat(scene.camera.eye);
    scene.camera.look = asFloat(scene.camera.look);
    for (CameraKey &k : scene.cameraAnimation.keys) { // as the camera line's own key
        k.camera.eye = asFloat(k.camera.eye);
        k.camera.look = asFloat(k.camera.look);
    }
    for (Light &l : scene.lights)
        l.position = asFloat(l.position);
    for (Sphere &s : scene.spheres)
        s.center = asFloat(s.center);
    for (Plane &p : scene.planes)
        p.point = asFloat(p.point);
    for (Instance &i : scene.instances)
        roundToFloat(i);
    for (PlacementTrack &track : scene.placementTracks)
        roundToFloat(track.first);
    for (MeshPrototype &m : scene.prototypes)
        for (Triangle &t : m.triangles)
            for (glm::dvec3 &p : t.p)
                p = asFloat(p);
}

void centerOnCamera(Scene &scene) {
    centerOn(scene, scene.camera.eye);
}

bool needsRecentering(const glm::dvec3 &eye, double viewDistance) {
    // A float's spacing at distance r from the origin is at most r * FLT_EPSILON.
    double coarsest = glm::length(eye) * double(FLT_EPSILON);
    return coarsest > 1e-5 * viewDistance;
}

} // namespace prism
