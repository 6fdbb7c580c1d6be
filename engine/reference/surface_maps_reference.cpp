#include "reference/surface_maps_reference.h"

#include <cmath>

namespace prism::reference {
namespace {

double bumpHeight(const Texture &map, glm::dvec2 uv) {
    return glm::dot(textureColor(map, uv), glm::dvec3(0.2126, 0.7152, 0.0722));
}

} // namespace

TangentFrame tangentFrame(glm::dvec3 n, glm::dvec3 dpdu, glm::dvec3 dpdv) {
    glm::dvec3 along = dpdu - glm::dot(dpdu, n) * n;
    double length = glm::length(along);
    if (!(length > 1e-6 * glm::length(dpdu))) {
        glm::dvec3 t = planeAxisU(n);
        return {t, glm::cross(n, t), n};
    }
    glm::dvec3 t = along / length;
    glm::dvec3 b = glm::cross(n, t);
    return {t, glm::dot(b, dpdv) < 0.0 ? -b : b, n};
}

glm::dvec2 bumpSlope(const Texture &map, glm::dvec2 uv) {
    glm::dvec2 size(map.width, map.height);
    glm::dvec2 texel = 1.0 / size;
    double du = bumpHeight(map, uv + glm::dvec2(texel.x, 0.0)) -
                bumpHeight(map, uv - glm::dvec2(texel.x, 0.0));
    double dv = bumpHeight(map, uv + glm::dvec2(0.0, texel.y)) -
                bumpHeight(map, uv - glm::dvec2(0.0, texel.y));
    return glm::dvec2(du, dv) * size * 0.5;
}

glm::dvec3 mappedNormal(const Scene &scene, const Surface &s, const Material &m) {
    if (!m.hasSurfaceMaps())
        return s.shadingNormal;
    TangentFrame frame = tangentFrame(s.shadingNormal, s.dpdu, s.dpdv);
    glm::dvec3 local(0.0, 0.0, 1.0);
    if (m.normalMap != kNoTexture)
        local = 2.0 * textureColor(scene.textures[size_t(m.normalMap)], s.uv) - 1.0;
    if (m.bumpMap != kNoTexture) {
        glm::dvec2 slope = bumpSlope(scene.textures[size_t(m.bumpMap)], s.uv);
        local.x -= double(m.bumpScale) * slope.x;
        local.y -= double(m.bumpScale) * slope.y;
    }
    glm::dvec3 mapped = local.x * frame.t + local.y * frame.b + local.z * frame.n;
    double length = glm::length(mapped);
    return length > 0.0 ? mapped / length : s.shadingNormal; // also for a NaN length
}

} // namespace prism::reference
