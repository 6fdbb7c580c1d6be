#pragma once
// Camera-relative coordinates. The GPU (and the grid built for it) work in 32-bit floats, whose
// spacing grows with distance from the origin: 2^-10 at 1e4, 1/16 at 1e6. A scene whose camera
// sits far from its file's origin would lose its detail exactly where the viewer looks. So the
// host keeps positions in double and, before building a grid or packing buffers, moves the
// scene's origin to the camera: floats are then finest where the viewer looks, as in
// large-world engines. The CPU reference renders the same centred scene, so it stays the oracle
// of what the GPU is given.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

// Moves the scene's origin to `point` (in the scene's current coordinates): every position is
// shifted by -point in double precision and Scene::origin records the total shift. Directions,
// radii and colours are unchanged, and so is the picture.
// `point` is taken by value: callers pass the scene's own camera.eye, which this moves.
void moveOrigin(Scene &scene, glm::dvec3 point);

// moveOrigin(scene, point), then every position rounded to the 32-bit float the GPU will be
// given, so that the grid (binned in double), the CPU reference and the GPU all see one and the
// same geometry. Rounding is lossy away from `point`: to centre again elsewhere, start from
// the uncentred scene (as prism-view keeps it), not from a centred one.
void centerOn(Scene &scene, glm::dvec3 point);

// An instance's placement rounded as centerOn rounds it: a keyed placement's at a later frame
// (scene/placement_animation.h) is rounded the same way as frame 1's.
void roundToFloat(Instance &instance);

// centerOn(scene, scene.camera.eye): what every renderer does to a loaded scene. An animated
// scene is centred on its frame-1 eye whatever frames are rendered, so that a frame is the same
// image in any range, chunk or tile of a farm (scene/camera_animation.h gives the other frames'
// cameras in the centred coordinates).
void centerOnCamera(Scene &scene);

// True when a camera that flew to `eye` is far enough from the scene's origin that floats
// there are coarser than 1/100000 of the viewing distance (~1% of a pixel at the point looked
// at): then the viewer re-centres (a grid rebuild) rather than lose precision.
bool needsRecentering(const glm::dvec3 &eye, double viewDistance);

} // namespace prism
