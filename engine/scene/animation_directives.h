#pragma once
// The .scene directives of camera animation (format 1.2, docs/scene-format.md, "Animation"):
// `key` (of the camera, or of a `place` line), `turntable` and `interpolate`, with their specs
// for the directive table.
#include "scene/directive_args.h"
#include "scene/scene_parser.h"

namespace prism {

extern const DirectiveSpec kCameraKeySpec, kPlaceKeySpec, kTurntableSpec, kInterpolateSpec;

// A key of the camera line above it, and of the place line above it (SceneBuilder::keyTarget).
void cameraKey(SceneBuilder &builder, const DirectiveArgs &args);
void placeKey(SceneBuilder &builder, const DirectiveArgs &args);
void turntable(SceneBuilder &builder, const DirectiveArgs &args);
void interpolate(SceneBuilder &builder, const DirectiveArgs &args);

} // namespace prism
