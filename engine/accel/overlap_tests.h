#pragma once
// Does a primitive overlap a box? Used to put each primitive only into the cells it touches.
#include <glm/glm.hpp>

namespace prism {

// Arvo 1990: the squared distance from the centre to the box against r^2.
bool sphereOverlapsBox(const glm::dvec3 &center, double radius, const glm::dvec3 &boxMin,
                       const glm::dvec3 &boxMax);

// Separating-axis test of Akenine-Moeller 2001 (13 axes: 3 box normals, the triangle normal,
// 9 edge cross products). Closed sets: touching counts as overlap.
bool triangleOverlapsBox(const glm::dvec3 &p0, const glm::dvec3 &p1, const glm::dvec3 &p2,
                         const glm::dvec3 &boxMin, const glm::dvec3 &boxMax);

} // namespace prism
