#pragma once
// Whitted ray tracing of one camera sample (shaders/trace.comp in double): Blinn-Phong with
// shadow rays, reflection and refraction, the ray tree walked with an explicit stack in the
// shader's order so both add the same terms.
#include <cstdint>

#include <glm/glm.hpp>

#include "core/ray_counts.h"
#include "reference/camera_model.h"
#include "reference/surface_reference.h"
#include "scene/scene.h"

namespace prism::reference {

// Which sample numbers (shared/sampling.h) a ray's area-light points use.
struct SampleId {
    uint32_t pixelIndex;
    uint32_t sampleIndex;
    uint32_t samplesPerPixel = 1; // area-light points are stratified across the pixel's samples
};

// Ambient plus Blinn-Phong from every light whose shadow ray is clear. The normals face the
// viewer: the geometric one, the unmapped shading one `smoothN` (with the geometric one, what
// decides whether a light lies behind the surface) and `n`, which shades (bent by normal and
// bump maps). `depth` is the ray's (1 = primary). Counts the shadow rays it traces.
glm::dvec3 directLight(const Scene &scene, const Surface &s, glm::dvec3 facingGeometric,
                       glm::dvec3 smoothN, glm::dvec3 n, glm::dvec3 view, glm::dvec3 color,
                       const Material &m, SampleId sample, uint32_t depth, RayCounts &rays);

// Radiance along a primary ray (depth 1) with rays up to maxDepth. Counts shadow and secondary
// rays (not the primary one).
glm::dvec3 traceRadiance(const Scene &scene, const Ray &primary, SampleId sample, uint32_t maxDepth,
                         RayCounts &rays);

} // namespace prism::reference
