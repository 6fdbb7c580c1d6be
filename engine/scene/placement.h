#pragma once
// Where a `place` line (and a keyed placement at any frame) puts its prototype: the transform as
// written with the prototype's centre taken in, and the checks that keep it within 32-bit floats.
#include <string>

#include <glm/glm.hpp>

#include "scene/mesh_transform.h"
#include "scene/scene.h"

namespace prism {

// The instance that puts the mesh's vertex v (as its `mesh ... as` line placed it, before
// centring) at translate + scale * R * v, R the rotations in the order written, exactly as a
// `mesh` line with these keys would. The prototype holds v - centre, so the instance's
// translation takes the centre in. Prototype and material are left to the caller.
Instance placedInstance(const MeshTransform &transform, const glm::dvec3 &centre);

// Why `instance` of prototype `name`, whose centred box is [boxMin, boxMax], cannot be traced in
// 32-bit floats (a corner of its box out of range, or a scale too small to undo), or "" when it
// can.
std::string placementProblem(const Instance &instance, const glm::dvec3 &boxMin,
                             const glm::dvec3 &boxMax, const std::string &name);

} // namespace prism
