#pragma once
// The values of a .scene directive's tokens (numbers, points, vectors), each throwing the line's
// LineError when a token is not what it should be; shared by the directive handlers.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/directive_args.h"
#include "scene/mesh_transform.h"
#include "scene/scene.h"
#include "scene/tokenizer.h"

namespace prism {

using Values = std::vector<const Token *>;

float number(const Token *token);
double coordinate(const Token *token); // a position's part: double precision
glm::vec3 vec3At(const Values &values, size_t first = 0);
// Positions keep double precision (scene/scene_origin.h says why).
glm::dvec3 pointAt(const Values &values, size_t first = 0);
std::string formatted(glm::dvec3 v); // "X Y Z" for messages

// Throws LineError unless `camera` sees something: eye and look apart, up not zero nor along the
// view. `what` names it in the message ("camera", "key").
void checkCameraView(const Camera &camera, const std::string &what);

// `scale`, `rotate` and `translate`, as `mesh`, `place` and a place's `key` take them, into
// `transform` (a rotation is appended); false for other keys.
bool placementValue(const KeyedValues &kv, MeshTransform &transform);

} // namespace prism
