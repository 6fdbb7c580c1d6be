#pragma once
// Instances written out as plain triangles: every placement's own copy of its prototype's
// triangles, in scene space. The tracer never does this (that is what instancing saves); the CPU
// reference and the Embree baseline do, so that they check the tracer's two-level walk against
// geometry that has only one level.
#include "scene/scene.h"

namespace prism {

// The triangles of `instance`, placed (positions, and vertex normals turned with it), with the
// shading records they point to: its prototype, placed.
MeshPrototype placedTriangles(const Scene &scene, const Instance &instance);

// `scene` with every instance's triangles appended to Scene::triangles (where Scene::instances
// puts them now) and no prototypes, instances or placement keys left.
Scene flattenInstances(Scene scene);

} // namespace prism
