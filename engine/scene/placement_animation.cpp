#include "scene/placement_animation.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "scene/key_interpolation.h"
#include "scene/number_parser.h"
#include "scene/placement.h"
#include "scene/scene_origin.h"

namespace prism {
namespace {

// The placement as written at `frame` (file coordinates, the prototype's centre not taken in).
MeshTransform keyedTransform(const Scene &scene, const PlacementTrack &track, double frame) {
    const std::vector<PlacementKey> &keys = track.keys;
    if (frame >= keys.back().frame)
        return keys.back().transform;
    KeySegment segment = keySegment(keys, frame);
    if (segment.u == 0.0)
        return keys[segment.i].transform;
    KeyInterpolation mode = scene.keyInterpolation;
    MeshTransform t = keys[segment.i].transform;
    t.scale = blendKeys<double>(keys, segment, mode,
                                [](const PlacementKey &k) { return k.transform.scale; });
    t.translation = blendKeys<glm::dvec3>(
        keys, segment, mode, [](const PlacementKey &k) { return k.transform.translation; });
    for (size_t r = 0; r < t.rotations.size(); ++r)
        t.rotations[r].degrees = blendKeys<double>(keys, segment, mode, [r](const PlacementKey &k) {
            return k.transform.rotations[r].degrees;
        });
    return t;
}

} // namespace

Instance placementAt(const Scene &scene, const PlacementTrack &track, double frame) {
    const Instance &first = track.first;
    if (frame <= track.keys.front().frame)
        return first;
    MeshTransform transform = keyedTransform(scene, track, frame);
    Instance instance = placedInstance(transform, track.centre);
    instance.prototype = first.prototype;
    instance.material = first.material;
    std::string problem;
    if (!(instance.scale > 0.0))
        problem = "its scale is " + formatNumber(instance.scale);
    else
        problem = placementProblem(instance, track.boxMin, track.boxMax,
                                   scene.prototypes[first.prototype].name);
    if (!problem.empty()) {
        KeySegment segment = keySegment(track.keys, frame);
        throw Error("frame " + formatNumber(frame) + ": the placement between the keys of line " +
                    std::to_string(track.keys[segment.i].line) + " and line " +
                    std::to_string(track.keys[segment.i + 1].line) + " cannot be traced (" +
                    problem + "); move the keys apart or use 'interpolate linear'");
    }
    instance.translation -= scene.origin;
    roundToFloat(instance);
    return instance;
}

double lastAnimatedFrame(const Scene &scene) {
    const CameraAnimation &a = scene.cameraAnimation;
    double last = a.keys.empty() ? 1.0 : a.keys.back().frame;
    if (a.turntable)
        last = std::max(last, a.turntable->frames);
    for (const PlacementTrack &track : scene.placementTracks)
        last = std::max(last, track.keys.back().frame);
    return last;
}

std::vector<Instance> instancesAt(const Scene &scene, double frame) {
    std::vector<Instance> instances = scene.instances;
    for (const PlacementTrack &track : scene.placementTracks)
        instances[track.instance] = placementAt(scene, track, frame);
    return instances;
}

} // namespace prism
