#pragma once
// Small triangle solids for the generated scenes, written inline as `v`/`f` lines. Every face is
// counter-clockwise seen from outside (the format's front face) and none has zero area, so the
// loader keeps them all.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene_text.h"

namespace prism::scenegen {

struct Solid {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<int, 3>> faces; // 0-based indices into vertices
};

Solid tetrahedron(double edge);             // regular, resting on a face at y = 0
Solid octahedron(double radius);            // vertices at +-radius on each axis
Solid box(const glm::dvec3 &size);          // centred on the origin
Solid icosphere(double radius, int levels); // 20 * 4^levels faces
// Ring of `majorSegments` x `minorSegments` quads around the y axis (lying flat).
Solid torus(double majorRadius, double minorRadius, int majorSegments, int minorSegments);
// Rectangle through the origin spanning `u` and `v`; its front faces along u x v.
Solid quad(const glm::dvec3 &u, const glm::dvec3 &v);

// Transforms in the order the `mesh` directive uses: scale, rotate about y (degrees), translate.
Solid placed(Solid solid, double scale, double yDegrees, const glm::dvec3 &translation);
Solid rotatedX(Solid solid, double degrees);

// Appends "use MATERIAL", the solid's `v` lines and `f` lines (negative, relative indices, so
// each block stands alone). Vertices are rounded to the scene files' four decimals.
void writeSolid(SceneText &out, const Solid &solid, const std::string &material);

} // namespace prism::scenegen
