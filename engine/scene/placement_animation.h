#pragma once
// The instances of a scene with keyed placements at any frame (format 1.2, docs/scene-format.md,
// "Animation"): each keyed instance's scale, angles and translation interpolated through its
// keys as the camera's are, linearly or by Catmull-Rom splines; an angle keyed 0 then 360 turns
// once. No grid here: session/prepared_scene.h rebuilds the level the instances are in.
#include <vector>

#include "scene/scene.h"

namespace prism {

// Whether any instance moves.
inline bool placementsAnimated(const Scene &scene) {
    return !scene.placementTracks.empty();
}

// The placement of the track's instance at `frame`, in the scene's current coordinates and
// rounded to floats as a centred scene's are (scene/scene_origin.h): at frame 1, and before it,
// PlacementTrack::first. Before the first key and after the last the instance holds still.
// Throws prism::Error naming the frame and the keys' lines when a spline between keys takes
// the scale to 0 or below, or the prototype's box out of the range of 32-bit floats.
Instance placementAt(const Scene &scene, const PlacementTrack &track, double frame);

// Whether anything moves: the camera (keys, a turntable) or an instance.
inline bool sceneAnimated(const Scene &scene) {
    return scene.cameraAnimation.animated() || placementsAnimated(scene);
}

// The animation's last frame: the later of a turntable's frame count (frame count + 1 is frame
// 1 again) and the last key's frame, the camera's or a placement's; 1 for a still scene.
double lastAnimatedFrame(const Scene &scene);

// Every instance at `frame`: Scene::instances with each keyed one at placementAt (whatever frame
// Scene::instances holds now).
std::vector<Instance> instancesAt(const Scene &scene, double frame);

} // namespace prism
