#pragma once
// The camera of an animated scene at any frame (format 1.2, docs/scene-format.md, "Animation"):
// keys interpolated linearly or by Catmull-Rom splines, or a turntable's orbit.
#include "scene/scene.h"

namespace prism {

// The camera at `frame`, in the scene's current coordinates (a centred scene gives centred
// cameras: scene/scene_origin.h moves the keys with everything else). Frame 1, and a scene
// without animation at any frame, give Scene::camera exactly. Before the first key and after
// the last the camera holds still. Throws prism::Error naming the frame and the keys' lines when
// the keys blend into a camera that sees nothing (eye at look, up along the view).
Camera cameraAt(const Scene &scene, double frame);

} // namespace prism
