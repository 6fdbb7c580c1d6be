#pragma once
// Vertex normals for a mesh that has none (`mesh ... smooth [ANGLE]`): its facets shade as one
// smooth surface, except across creases and smoothing groups.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace prism {

// A triangle by its corners' indices into the mesh's positions, counter-clockwise. Corners with
// the same index are one vertex (the importer welds equal positions to one index first).
struct SmoothingTriangle {
    std::array<uint32_t, 3> vertex;
    uint32_t group = 0; // OBJ smoothing group; normals are shared within one only
};

// The normal of each triangle's corners: the angle-weighted mean (Thürmer and Wüthrich 1998)
// of the unit geometric normals of the triangles around that vertex that are in the corner's
// smoothing group and meet the corner's own triangle at no more than `creaseDegrees`.
// Weighting by the corner angle makes the normal a property of the surface, not of how it was
// cut into triangles: a quad fanned into two triangles, or a vertex with many thin slivers on
// one side, does not pull the normal over (area weighting would favour big facets, plain means
// the side with more triangles). Results are unit length.
// On every core; the same normals whatever the thread count.
std::vector<std::array<glm::vec3, 3>>
smoothVertexNormals(std::span<const glm::dvec3> positions,
                    const std::vector<SmoothingTriangle> &triangles, double creaseDegrees);

} // namespace prism
