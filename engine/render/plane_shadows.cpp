#include "render/plane_shadows.h"

#include <algorithm>
#include <cmath>

#include "shared/gpu_types.h"

namespace prism {
namespace {

// Relative margin, as in traced_tiles.cpp: far above float rounding (a few 1e-7), far below
// anything that would cost a tile.
constexpr double kEpsilon = 1e-5;

double maxAbs(const glm::dvec3 &v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// The shadow region of `box` from `light` on plane (n, w), boxed; false when it has no bound.
bool shadowBox(const Aabb &box, const glm::dvec4 &plane, const Light &light, Aabb &out) {
    glm::dvec3 n(plane), L = light.position;
    double nn = glm::dot(n, n);
    double hL = glm::dot(n, L) - plane.w;
    double scale = std::max({maxAbs(box.min), maxAbs(box.max), maxAbs(L), std::abs(plane.w)});
    if (!(std::abs(hL) > kEpsilon * scale * std::sqrt(nn)))
        return false; // the light on (or nearly on) the plane
    // The box grown by the light's radius and a margin for rounding.
    glm::dvec3 grow(double(light.radius) * (1.0 + kEpsilon) + kEpsilon * scale);
    glm::dvec3 lo = box.min - grow, hi = box.max + grow;
    glm::dvec3 foot = L - n * (hL / nn);
    out = Aabb{};
    double reach = 0.0; // the farthest projected corner from the foot
    for (int k = 0; k < 8; ++k) {
        glm::dvec3 c((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        double hc = glm::dot(n, c) - plane.w;
        // The corner must lie clearly nearer the plane than the light, on the light's side.
        double below = hL > 0.0 ? hL - hc : hc - hL;
        if (!(below > kEpsilon * (std::abs(hL) + std::abs(hc))))
            return false;
        glm::dvec3 q = L + (c - L) * (hL / (hL - hc));
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
            return false;
        out.grow(q);
        reach = std::max(reach, glm::length(q - foot));
    }
    // The ray's offset e lifts its origin off the plane, which shrinks the region towards the
    // foot by e / h(L): at most e * reach / h(L), with e at most the offset of the farthest
    // point of the region or the foot. The projection magnifies rounding by as much: the
    // relative margin times the same factor.
    double magnify = 1.0 + reach * std::sqrt(nn) / std::abs(hL);
    double farthest = std::max({maxAbs(out.min), maxAbs(out.max), maxAbs(foot)});
    double pad =
        (kEpsilon * std::max(farthest, scale) + PRISM_OFFSET_RELATIVE * farthest) * magnify;
    out.min -= pad;
    out.max += pad;
    return std::isfinite(pad);
}

// p reflected in plane (n, w).
glm::dvec3 mirrored(const glm::dvec3 &p, const glm::dvec4 &plane) {
    glm::dvec3 n(plane);
    return p - n * (2.0 * (glm::dot(n, p) - plane.w) / glm::dot(n, n));
}

} // namespace

std::vector<Aabb> planeMirrorBoxes(const std::vector<Aabb> &boxes, const glm::dvec4 &plane,
                                   const glm::dvec3 &eye, double spread) {
    std::vector<Aabb> images;
    images.reserve(boxes.size());
    for (const Aabb &box : boxes) {
        Aabb image;
        double reach = 0.0; // the farthest corner of the image from the eye
        for (int k = 0; k < 8; ++k) {
            glm::dvec3 c((k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
                         (k & 4) ? box.max.z : box.min.z);
            glm::dvec3 m = mirrored(c, plane);
            image.grow(m);
            reach = std::max(reach, glm::length(m - eye));
        }
        double far = maxAbs(eye) + spread + reach;
        double pad = (kEpsilon + 2.0 * PRISM_OFFSET_RELATIVE) * far;
        image.min -= pad;
        image.max += pad;
        images.push_back(image);
    }
    return images;
}

std::optional<std::vector<Aabb>> planeShadowBoxes(const std::vector<Aabb> &boxes,
                                                  const std::vector<glm::dvec4> &planes,
                                                  const std::vector<Light> &lights) {
    std::vector<Aabb> casters = boxes;
    if (casters.size() * planes.size() * lights.size() > kMaxPlaneShadowBoxes) {
        Aabb all;
        for (const Aabb &b : boxes)
            all.grow(b);
        casters.assign(1, all);
    }
    std::vector<Aabb> shadows;
    if (casters.empty())
        return shadows;
    shadows.reserve(casters.size() * planes.size() * lights.size());
    for (const Light &light : lights)
        for (const glm::dvec4 &plane : planes)
            for (const Aabb &box : casters) {
                Aabb shadow;
                if (!shadowBox(box, plane, light, shadow))
                    return std::nullopt;
                shadows.push_back(shadow);
            }
    return shadows;
}

std::optional<PlaneTileGuards> planeTileGuards(const std::vector<Aabb> &boxes,
                                               const std::vector<glm::dvec4> &planes,
                                               const std::vector<Light> &lights, bool shadows,
                                               std::optional<size_t> mirror) {
    auto shadowsOn = [&](const std::vector<glm::dvec4> &on) {
        return shadows ? planeShadowBoxes(boxes, on, lights) : std::vector<Aabb>{};
    };
    std::optional<std::vector<Aabb>> all = shadowsOn(planes);
    if (!all)
        return std::nullopt;
    PlaneTileGuards guards;
    guards.shadows = std::move(*all);
    if (mirror) {
        std::vector<glm::dvec4> others = planes;
        others.erase(others.begin() + std::ptrdiff_t(*mirror));
        std::vector<Aabb> otherShadows = shadowsOn(others).value(); // a subset: bounded too
        guards.mirror = planes[*mirror];
        guards.mirrorCasters = boxes;
        guards.mirrorCasters.insert(guards.mirrorCasters.end(), otherShadows.begin(),
                                    otherShadows.end());
    }
    return guards;
}

std::vector<Aabb> needGridBoxes(const PlaneTileGuards &guards, const gpu::GpuFrameParams &frame) {
    std::vector<Aabb> boxes = guards.shadows;
    if (guards.mirror) {
        // A parallel camera's rays start up to its half-width and half-height from the eye.
        double spread = gpu::isParallelCamera(frame)
                            ? glm::length(glm::dvec3(frame.du)) + glm::length(glm::dvec3(frame.dv))
                            : 0.0;
        std::vector<Aabb> mirrors =
            planeMirrorBoxes(guards.mirrorCasters, *guards.mirror, glm::dvec3(frame.eye), spread);
        boxes.insert(boxes.end(), mirrors.begin(), mirrors.end());
    }
    return boxes;
}

} // namespace prism
