#pragma once
// The .scene directives of camera animation (format 1.2, docs/scene-format.md, "Animation"):
// `key`, `turntable` and `interpolate`, with their specs for the directive table.
#include "scene/directive_args.h"
#include "scene/scene_parser.h"

namespace prism {

extern const DirectiveSpec kKeySpec, kTurntableSpec, kInterpolateSpec;

void cameraKey(SceneBuilder &builder, const DirectiveArgs &args);
void turntable(SceneBuilder &builder, const DirectiveArgs &args);
void interpolate(SceneBuilder &builder, const DirectiveArgs &args);

} // namespace prism
