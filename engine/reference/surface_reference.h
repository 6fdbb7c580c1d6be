#pragma once
// A hit turned into what shading needs (shaders/surface.glsl in double): position rebuilt from
// the primitive, normals, texture coordinates, material; texture lookups; ray offsets.
#include <cstdint>

#include <glm/glm.hpp>

#include "reference/camera_model.h"
#include "reference/scene_query.h"
#include "scene/scene.h"

namespace prism::reference {

struct Surface {
    glm::dvec3 position;
    glm::dvec3 geometricNormal; // the primitive's own: sphere outward, plane given, triangle ABC
    glm::dvec3 shadingNormal;   // interpolated vertex normal where present, else geometricNormal
    glm::dvec2 uv;
    uint32_t material;
    // Where shadow rays leave from: `position`, or on a triangle with vertex normals seen from
    // its front, the point of the smooth surface those normals describe (smoothSurfacePoint).
    glm::dvec3 shadowPosition;
    bool smooth = false; // vertex normals: the horizon for shadow rays is the shading normal's
    // Directions of increasing u and v on the surface (any length; zero where the UVs have no
    // area), for the tangent frame of normal and bump maps (surface_maps_reference.h).
    glm::dvec3 dpdu{0.0};
    glm::dvec3 dpdv{0.0};
};

// Hanika, "Hacking the Shadow Terminator" (Ray Tracing Gems II, 2021): p projected onto each
// vertex's tangent plane where it lies below it, the projections blended by the barycentrics
// b. On a coarse smooth-shaded mesh this lifts the shadow ray's origin from the flat facet to
// the curved surface the shading normals describe, so facets do not shadow their neighbours
// at the terminator (the stair-step dark band) and no light leaks: points above every tangent
// plane stay where they are.
glm::dvec3 smoothSurfacePoint(glm::dvec3 p, const glm::dvec3 corner[3], const glm::dvec3 normal[3],
                              const double b[3]);

// `hit` must be a hit of `ray` in `scene` (kind != None).
Surface surfaceAt(const Scene &scene, const Ray &ray, const Hit &hit);

// Plane texture axes: a1 = normalize(n x e) with e the world axis least aligned with n (x before
// y before z on ties), a2 = n x a1; (u, v) = (P . a1, P . a2).
glm::dvec2 planeUV(glm::dvec3 p, glm::dvec3 n);
glm::dvec3 planeAxisU(glm::dvec3 n); // a1 above

// Bilinear lookup with wrap-around; v = 0 is the image's bottom row (texels are stored top row
// first).
glm::dvec3 textureColor(const Texture &texture, glm::dvec2 uv);

// What a ray leaving along `dir` that hits nothing sees: Scene::environment's lat-long image
// where there is one (docs/scene-format.md), else the background.
glm::dvec3 missColor(const Scene &scene, glm::dvec3 dir);

// Origin for a ray leaving `position` in `dir`: moved along the facing geometric normal, to the
// side the ray leaves from, by PRISM_OFFSET_RELATIVE * max|P_i| (never a fixed epsilon).
glm::dvec3 offsetOrigin(glm::dvec3 position, glm::dvec3 facingNormal, glm::dvec3 dir);

} // namespace prism::reference
