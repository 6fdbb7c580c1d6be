#include "reference/trace_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "reference/scene_query.h"
#include "reference/surface_maps_reference.h"
#include "shared/sampling.h"

namespace prism::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Uniform point on a sphere of radius 1 from two uniform numbers (z = 1 - 2u, phi = 2 pi v), as
// the shader picks area-light points.
glm::dvec3 uniformSpherePoint(double u, double v) {
    double z = 1.0 - 2.0 * u;
    double rxy = std::sqrt(std::max(0.0, 1.0 - z * z));
    double phi = 2.0 * kPi * v;
    return glm::dvec3(rxy * std::cos(phi), rxy * std::sin(phi), z);
}

struct PendingRay {
    Ray ray;
    glm::dvec3 weight;
    uint32_t depth;
};

glm::dvec3 surfaceColor(const Scene &scene, const Material &m, glm::dvec2 uv) {
    glm::dvec3 color(m.color);
    if (m.texture >= 0 && size_t(m.texture) < scene.textures.size())
        color *= textureColor(scene.textures[size_t(m.texture)], uv);
    return color;
}

} // namespace

glm::dvec3 directLight(const Scene &scene, const Surface &s, glm::dvec3 facingGeometric,
                       glm::dvec3 smoothN, glm::dvec3 n, glm::dvec3 view, glm::dvec3 color,
                       const Material &m, SampleId sample, uint32_t depth, RayCounts &rays) {
    glm::dvec3 result = double(m.ambient) * color * glm::dvec3(scene.ambient);
    uint32_t lightCount = uint32_t(scene.lights.size());
    for (uint32_t l = 0; l < lightCount; ++l) {
        const Light &light = scene.lights[l];
        glm::dvec3 center(light.position);
        // Shading aims at the light's centre; only the shadow ray aims at a sampled point.
        glm::dvec3 toLight = glm::normalize(center - s.position);
        double nDotL = glm::dot(n, toLight);
        if (!(nDotL > 0.0)) // also skips NaN, as the shader's `nDotL > 0.0` does
            continue;
        glm::dvec3 target = center;
        if (light.radius > 0.0f) {
            uint32_t dim = PRISM_DIM_LIGHT_BASE + 2u * ((depth - 1u) * lightCount + l);
            glm::vec2 u = gpu::stratifiedPair(sample.pixelIndex, sample.sampleIndex,
                                              sample.samplesPerPixel, dim);
            target += double(light.radius) * uniformSpherePoint(u.x, u.y);
        }
        // A target below the surface's own horizon is shadowed by the surface itself. With
        // vertex normals the surface is the smooth one they describe: its point and normal.
        // Never a mapped normal's horizon: a light behind the surface stays dark (no leaks).
        glm::dvec3 from = s.shadowPosition;
        glm::dvec3 horizon = s.smooth ? smoothN : facingGeometric;
        if (!(glm::dot(target - from, horizon) > 0.0))
            continue;
        glm::dvec3 origin = offsetOrigin(from, horizon, target - from);
        glm::dvec3 toTarget = target - origin;
        double distance = glm::length(toTarget);
        rays.shadow += 1;
        if (traceOccluded(scene, Ray{origin, toTarget / distance}, distance))
            continue;
        glm::dvec3 halfway = glm::normalize(toLight + view);
        double specular = std::pow(std::max(0.0, glm::dot(n, halfway)), double(m.shininess));
        result += glm::dvec3(light.color) *
                  (double(m.diffuse) * color * nDotL + double(m.specular) * specular);
    }
    return result;
}

glm::dvec3 traceRadiance(const Scene &scene, const Ray &primary, SampleId sample, uint32_t maxDepth,
                         RayCounts &rays) {
    // Explicit stack, popped last-in first-out like the shader's, so the terms are added in the
    // same order. It never holds more than 2 * maxDepth - 1 rays.
    std::vector<PendingRay> stack;
    stack.reserve(2 * size_t(maxDepth) + 1);
    stack.push_back({primary, glm::dvec3(1.0), 1u});
    glm::dvec3 radiance(0.0);
    while (!stack.empty()) {
        PendingRay pending = stack.back();
        stack.pop_back();
        const Ray &ray = pending.ray;
        if (pending.depth > 1u)
            rays.secondary += 1;
        Hit hit;
        if (!traceClosest(scene, ray, kInfinity, hit)) {
            radiance += pending.weight * missColor(scene, ray.dir);
            continue;
        }
        Surface s = surfaceAt(scene, ray, hit);
        const Material &m = scene.materials[s.material];
        glm::dvec3 view = -ray.dir;
        // Both normals turned to face the viewer.
        glm::dvec3 ng =
            glm::dot(s.geometricNormal, view) < 0.0 ? -s.geometricNormal : s.geometricNormal;
        // The side comes from the unmapped shading normal (a map never flips it); maps bend the
        // normal as it points, and the result is turned with the side.
        double side = glm::dot(s.shadingNormal, view) < 0.0 ? -1.0 : 1.0;
        glm::dvec3 smoothN = side * s.shadingNormal;
        glm::dvec3 n = side * mappedNormal(scene, s, m);
        glm::dvec3 color = surfaceColor(scene, m, s.uv);
        radiance += pending.weight * directLight(scene, s, ng, smoothN, n, view, color, m, sample,
                                                 pending.depth, rays);
        if (pending.depth >= maxDepth)
            continue;
        uint32_t childDepth = pending.depth + 1u;
        glm::dvec3 reflected = glm::reflect(ray.dir, n);
        auto push = [&](glm::dvec3 dir, glm::dvec3 weight) {
            stack.push_back({Ray{offsetOrigin(s.position, ng, dir), dir}, weight, childDepth});
        };
        if (m.reflect > 0.0f)
            push(reflected, pending.weight * double(m.reflect));
        if (m.transmit > 0.0f) {
            double ior = double(m.ior);
            // Entering or leaving is decided by the primitive's own normal, not the facing one.
            bool entering = glm::dot(ray.dir, s.geometricNormal) < 0.0;
            double eta = entering ? 1.0 / ior : ior;
            double cosI = -glm::dot(ray.dir, n);
            double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
            glm::dvec3 weight = pending.weight * double(m.transmit);
            if (k < 0.0) { // total internal reflection
                push(reflected, weight);
            } else {
                double f0 = (ior - 1.0) / (ior + 1.0);
                f0 *= f0;
                // Schlick's approximation; cosI can exceed 1 by an ulp, hence the clamp.
                double fresnel = f0 + (1.0 - f0) * std::pow(std::max(0.0, 1.0 - cosI), 5.0);
                glm::dvec3 refracted =
                    glm::normalize(eta * ray.dir + (eta * cosI - std::sqrt(k)) * n);
                push(reflected, weight * fresnel);
                push(refracted, weight * (1.0 - fresnel));
            }
        }
    }
    return radiance;
}

} // namespace prism::reference
