#pragma once
// Normal and bump maps in double (shaders/surface_maps.glsl written again, the oracle for it):
// the shading normal bent by a material's maps (docs/scene-format.md, "Normal and bump maps").
#include <glm/glm.hpp>

#include "reference/surface_reference.h"
#include "scene/scene.h"

namespace prism::reference {

struct TangentFrame {
    glm::dvec3 t, b, n;
};

// Orthonormal (t, b, n) for unit n: t is dp/du with its n part removed (Gram-Schmidt), b = n x t
// turned towards dp/dv, so +y follows +v even where the UVs are mirrored. Where dp/du is zero or
// along n (UVs without area, a sphere's pole) t is the plane texture axis of n (planeAxisU):
// any frame will do there, and this one is finite.
TangentFrame tangentFrame(glm::dvec3 n, glm::dvec3 dpdu, glm::dvec3 dpdv);

// dh/du and dh/dv of a bump map's height (Rec. 709 luminance of its data) in texture-coordinate
// units: central differences one texel either side of uv, on the bilinear lookup.
glm::dvec2 bumpSlope(const Texture &map, glm::dvec2 uv);

// s's shading normal (as it points, not turned to the viewer) with m's maps applied: in the
// tangent frame, (2 rgb - 1) of the normal map (OpenGL convention, +y = +v) or (0, 0, 1), less
// the bump map's slopes times its multiplier in x and y (Blinn 1978), normalised. The shading
// normal itself where m has no maps or the result has no length.
glm::dvec3 mappedNormal(const Scene &scene, const Surface &s, const Material &m);

} // namespace prism::reference
