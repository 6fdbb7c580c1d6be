#pragma once
// Where on the scene's planes a shadow ray may meet the grid's geometry. A tile whose camera rays
// can hit nothing but planes (render/traced_tiles.h) needs the grid only for the shadow rays of
// those plane hits, and only where a hit lies in the shadow of some box of geometry. Elsewhere
// the tile is traced by a variant with no grid at all: on lavapipe a walk that no lane of a SIMD
// group needs still costs a pass of each of its loops (docs/benchmarks.md, "Where the cycles
// go"), and most of a floor's pixels are such tiles.
//
// The geometry. A shadow ray runs from a point P of plane h(x) = n.x - w = 0 towards a light at
// L; it meets a convex box B exactly where P lies in the central projection of B from L onto the
// plane, which is the convex hull of B's projected corners as long as every corner is nearer the
// plane than L (on L's side; a corner on the far side of the plane projects between L and it,
// which only enlarges the hull). Three things widen that region, and the boxes cover them:
//  - A spherical light of radius r: a ray towards L + r u passes within r of the ray towards L
//    wherever it is, so B grown by r, projected from the centre, holds every such ray's hits.
//  - The ray leaves from P lifted off the plane by its offset e (towards the light; surface.glsl,
//    offsetOrigin). The cone from L through B, cut at height e above the plane and dropped back
//    onto it, is the projection shrunk towards the foot of L by the factor (h(L) - e) / h(L),
//    so it lies within e * (the projection's reach from the foot) / h(L) of the projection; e
//    is at most PRISM_OFFSET_RELATIVE of the largest coordinate there.
//  - Float rounding in the shader's ray and in the host's arithmetic: relative margins, and
//    more where the projection magnifies (a light low over the plane).
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "accel/bounds.h"
#include "scene/scene.h"
#include "shared/gpu_types.h"

namespace prism {

// More boxes than this (boxes x planes x lights) are not projected one by one: the union of the
// boxes is, once per plane and light, which is coarser and as safe.
constexpr size_t kMaxPlaneShadowBoxes = size_t(1) << 16;

// For each light, plane (n, w) with n.x = w on the plane, and box: a box round the box's shadow
// region on the plane, as above, grown by the offset's and rounding's margins. nullopt where some
// region has no bound: a corner of a grown box as far from the plane as the light, or farther, on
// the light's side; or a light on a plane. Empty when there are no boxes, planes or lights.
std::optional<std::vector<Aabb>> planeShadowBoxes(const std::vector<Aabb> &boxes,
                                                  const std::vector<glm::dvec4> &planes,
                                                  const std::vector<Light> &lights);

// Where a reflection off a mirror plane (n, w) may reach a box. The ray a plane hit reflects is
// the mirror image of the camera ray continued through the plane, so it meets a box exactly
// where the camera ray, past its hit, meets the box's mirror image: a tile whose rays may pass
// through a mirror image needs the grid. The reflected ray leaves from its offset origin, which
// shifts the mirror image of its line by at most that offset: for a camera ray that gets near
// a mirror image at distance D from the eye the hit is nearer than D, so the offset is at most
// PRISM_OFFSET_RELATIVE (|eye| + D). The mirror images of `boxes`, grown by that and by
// rounding, for a camera at `eye` whose rays start within `spread` of it (a parallel camera's
// half-width and half-height; 0 for perspective). Exact for a plane whose shading normal is its
// normal (no normal or bump map) and where a reflected ray that misses the boxes meets nothing
// else (no other plane).
std::vector<Aabb> planeMirrorBoxes(const std::vector<Aabb> &boxes, const glm::dvec4 &plane,
                                   const glm::dvec3 &eye, double spread);

// What decides, for a scene, which tiles that see only planes may go without the grid.
struct PlaneTileGuards {
    std::vector<Aabb> shadows;        // planeShadowBoxes of every plane
    std::optional<glm::dvec4> mirror; // the one plane that reflects, if any (the rest are matte)
    // What the mirror's reflections may meet: the blocks, and the other planes' shadow boxes (a
    // reflection that meets a matte plane shades it; nothing follows from there).
    std::vector<Aabb> mirrorCasters;
};

// The guards of the blocks `boxes` over `planes` lit by `lights` (no shadow boxes when
// `shadows` is off), with planes[*mirror] the one mirror; nullopt where some shadow has no
// bound.
std::optional<PlaneTileGuards> planeTileGuards(const std::vector<Aabb> &boxes,
                                               const std::vector<glm::dvec4> &planes,
                                               const std::vector<Light> &lights, bool shadows,
                                               std::optional<size_t> mirror);

// The boxes that a frame's camera rays must miss for a tile that sees only planes to go without
// the grid: the shadow boxes, and the mirror images of what reflections may meet, grown for
// this camera (planeMirrorBoxes).
std::vector<Aabb> needGridBoxes(const PlaneTileGuards &guards, const gpu::GpuFrameParams &frame);

} // namespace prism
