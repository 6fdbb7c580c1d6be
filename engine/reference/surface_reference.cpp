#include "reference/surface_reference.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

#include "reference/intersect_reference.h"
#include "shared/gpu_types.h"

namespace prism::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Texel index of `base` wrapped into [0, size): floor-modulo, safe for any finite base.
int wrapIndex(double base, int size) {
    double wrapped = base - double(size) * std::floor(base / double(size));
    return std::clamp(int(wrapped), 0, size - 1);
}

double signOf(double x) {
    return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
}

// dp/du and dp/dv of a triangle from the UV differences d1, d2 along its edges e1, e2
// (Lengyel): the solution of e = du * dp/du + dv * dp/dv, times sign(det) instead of divided
// by det, as only directions matter; zero when the UVs have no area.
void triangleTangents(glm::dvec3 e1, glm::dvec3 e2, glm::dvec2 d1, glm::dvec2 d2, Surface &s) {
    double det = d1.x * d2.y - d1.y * d2.x;
    s.dpdu = signOf(det) * (d2.y * e1 - d1.y * e2);
    s.dpdv = signOf(det) * (d1.x * e2 - d2.x * e1);
}

} // namespace

Surface surfaceAt(const Scene &scene, const Ray &ray, const Hit &hit) {
    // Hit points are rebuilt from the primitive (not origin + t * dir) so their error is
    // relative to |P|, which is what the relative ray offset assumes.
    Surface s{};
    switch (hit.kind) {
    case HitKind::Sphere: {
        const Sphere &sphere = scene.spheres[hit.index];
        glm::dvec3 center(sphere.center);
        glm::dvec3 n = glm::normalize(ray.origin + hit.t * ray.dir - center);
        s.position = center + double(sphere.radius) * n;
        s.shadowPosition = s.position;
        s.geometricNormal = n;
        s.shadingNormal = n;
        s.uv = glm::dvec2(0.5 + std::atan2(n.z, n.x) / (2.0 * kPi),
                          0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / kPi);
        // d/du along the parallel (u turns with atan2(z, x)), d/dv along the meridian, up.
        s.dpdu = glm::dvec3(-n.z, 0.0, n.x);
        s.dpdv = glm::dvec3(-n.y * n.x, n.x * n.x + n.z * n.z, -n.y * n.z);
        s.material = sphere.material;
        break;
    }
    case HitKind::Plane: {
        const Plane &plane = scene.planes[hit.index];
        PlaneEquation eq = planeEquation(plane);
        glm::dvec3 p = ray.origin + hit.t * ray.dir;
        s.position = p - (glm::dot(eq.normal, p) - eq.offset) * eq.normal; // project onto it
        s.shadowPosition = s.position;
        s.geometricNormal = eq.normal;
        s.shadingNormal = eq.normal;
        s.uv = planeUV(s.position, eq.normal);
        s.dpdu = planeAxisU(eq.normal);
        s.dpdv = glm::cross(eq.normal, s.dpdu);
        s.material = plane.material;
        break;
    }
    case HitKind::None:
        break; // nothing was hit: no surface
    case HitKind::Triangle: {
        const Triangle &tri = scene.triangles[hit.index];
        const TriangleShading &shading = shadingOf(tri, scene.triangleShading);
        double b1 = hit.b12.x, b2 = hit.b12.y, b0 = 1.0 - b1 - b2;
        glm::dvec3 p0(tri.p[0]), p1(tri.p[1]), p2(tri.p[2]);
        s.position = b0 * p0 + b1 * p1 + b2 * p2;
        s.geometricNormal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
        s.shadingNormal = s.geometricNormal;
        s.uv = glm::dvec2(b1, b2);
        s.shadowPosition = s.position;
        if (shading.hasNormals) {
            s.shadingNormal =
                glm::normalize(b0 * glm::dvec3(shading.n[0]) + b1 * glm::dvec3(shading.n[1]) +
                               b2 * glm::dvec3(shading.n[2]));
            s.smooth = true;
            if (glm::dot(ray.dir, s.geometricNormal) < 0.0) { // the front: where normals point
                const glm::dvec3 corner[3] = {p0, p1, p2};
                const glm::dvec3 normal[3] = {glm::dvec3(shading.n[0]), glm::dvec3(shading.n[1]),
                                              glm::dvec3(shading.n[2])};
                const double b[3] = {b0, b1, b2};
                s.shadowPosition = smoothSurfacePoint(s.position, corner, normal, b);
            }
        }
        // Without texture coordinates (u, v) = (b1, b2): corners (0, 0), (1, 0), (0, 1).
        glm::dvec2 uv[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
        if (shading.hasUVs) {
            for (int c = 0; c < 3; ++c)
                uv[c] = glm::dvec2(shading.uv[c]);
            s.uv = b0 * uv[0] + b1 * uv[1] + b2 * uv[2];
        }
        triangleTangents(p1 - p0, p2 - p0, uv[1] - uv[0], uv[2] - uv[0], s);
        s.material = tri.material;
        break;
    }
    }
    return s;
}

glm::dvec3 smoothSurfacePoint(glm::dvec3 p, const glm::dvec3 corner[3], const glm::dvec3 normal[3],
                              const double b[3]) {
    glm::dvec3 lifted(0.0);
    for (int i = 0; i < 3; ++i) {
        double below = std::min(0.0, glm::dot(p - corner[i], normal[i]));
        lifted += b[i] * (p - below * normal[i]);
    }
    return lifted;
}

glm::dvec3 missColor(const Scene &scene, glm::dvec3 dir) {
    const Environment &e = scene.environment;
    if (e.texture == kNoTexture)
        return glm::dvec3(scene.background);
    const Texture &image = scene.textures[size_t(e.texture)];
    glm::dvec3 d = glm::normalize(dir);
    double pi = glm::pi<double>();
    double u = 0.5 + (std::atan2(d.x, -d.z) - glm::radians(double(e.rotateDegrees))) / (2.0 * pi);
    double v = 0.5 + std::asin(std::clamp(d.y, -1.0, 1.0)) / pi;
    double halfTexel = 0.5 / double(image.height); // no wrap over the poles
    return double(e.intensity) *
           textureColor(image, glm::dvec2(u, std::clamp(v, halfTexel, 1.0 - halfTexel)));
}

glm::dvec3 planeAxisU(glm::dvec3 n) {
    glm::dvec3 a = glm::abs(n);
    glm::dvec3 axis = (a.x <= a.y && a.x <= a.z)
                          ? glm::dvec3(1, 0, 0)
                          : (a.y <= a.z ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1));
    return glm::normalize(glm::cross(n, axis));
}

glm::dvec2 planeUV(glm::dvec3 p, glm::dvec3 n) {
    glm::dvec3 a1 = planeAxisU(n);
    return glm::dvec2(glm::dot(p, a1), glm::dot(p, glm::cross(n, a1)));
}

glm::dvec3 textureColor(const Texture &texture, glm::dvec2 uv) {
    int w = texture.width, h = texture.height;
    if (w <= 0 || h <= 0 || texture.texels.size() < size_t(w) * size_t(h) || !std::isfinite(uv.x) ||
        !std::isfinite(uv.y))
        return glm::dvec3(0.0); // nothing sensible to look up
    // Texel centres sit at half-integers; bilinear weights from the fractional part.
    glm::dvec2 xy = glm::dvec2(uv.x * double(w), uv.y * double(h)) - 0.5;
    glm::dvec2 base = glm::floor(xy);
    glm::dvec2 f = xy - base;
    int x0 = wrapIndex(base.x, w), y0 = wrapIndex(base.y, h);
    int x1 = (x0 + 1) % w, y1 = (y0 + 1) % h;
    // Bottom-based rows map to stored rows h-1-y.
    size_t rowA = size_t(h - 1 - y0) * size_t(w), rowB = size_t(h - 1 - y1) * size_t(w);
    auto texel = [&](size_t row, int x) { return glm::dvec4(texture.texels[row + size_t(x)]); };
    glm::dvec4 c00 = texel(rowA, x0), c10 = texel(rowA, x1);
    glm::dvec4 c01 = texel(rowB, x0), c11 = texel(rowB, x1);
    return glm::dvec3(glm::mix(glm::mix(c00, c10, f.x), glm::mix(c01, c11, f.x), f.y));
}

glm::dvec3 offsetOrigin(glm::dvec3 position, glm::dvec3 facingNormal, glm::dvec3 dir) {
    // The same relative offset as the shader (shared/gpu_types.h), so both agree on which
    // nearby surfaces a new ray can see.
    glm::dvec3 a = glm::abs(position);
    double eps = std::max(std::max(a.x, std::max(a.y, a.z)), double(PRISM_OFFSET_FLOOR)) *
                 double(PRISM_OFFSET_RELATIVE);
    return position + (glm::dot(dir, facingNormal) >= 0.0 ? eps : -eps) * facingNormal;
}

} // namespace prism::reference
