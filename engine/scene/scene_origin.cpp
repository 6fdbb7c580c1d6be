#include "scene/scene_origin.h"

#include <cfloat>

namespace prism {

void moveOrigin(Scene &scene, glm::dvec3 point) {
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
    for (Triangle &t : scene.triangles)
        for (glm::dvec3 &p : t.p)
            p -= point;
    for (Instance &i : scene.instances) // prototypes live in their own space
        i.translation -= point;
    for (PlacementTrack &track : scene.placementTracks)
        track.first.translation -= point;
}

namespace {

// Out of line on purpose: GCC 12's SLP vectoriser, given double(float(x)) for the three
// components inline, folds the pair of conversions into nothing at -O2 (measured: 1000000.3 -
// 1000000.25 stayed 0.050000000047 instead of the float 0.050000000745). Behind a call the
// truncation happens.
[[gnu::noinline]] float toFloat(double x) {
    return float(x);
}

glm::dvec3 asFloat(const glm::dvec3 &p) {
    return {toFloat(p.x), toFloat(p.y), toFloat(p.z)};
}

} // namespace

void roundToFloat(Instance &instance) {
    instance.translation = asFloat(instance.translation);
    instance.scale = toFloat(instance.scale);
    for (int c = 0; c < 3; ++c)
        instance.rotation[c] = asFloat(instance.rotation[c]);
}

void centerOn(Scene &scene, glm::dvec3 point) {
    moveOrigin(scene, point);
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
    for (Triangle &t : scene.triangles)
        for (glm::dvec3 &p : t.p)
            p = asFloat(p);
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
