#include "render/traced_tiles.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace prism {
namespace {

// Relative margin of every sign test below: far above the float rounding of the shader's ray
// (a few 1e-7), far below the pixel of margin round each tile (1e-3 of the image at 1024).
constexpr double kEpsilon = 1e-5;

struct TileSpan {
    double x0, x1, y0, y1; // image-plane coordinates in [-1, 1], y up, with a pixel's margin
};

TileSpan tileSpan(uint32_t tx, uint32_t ty, double width, double height) {
    // Sample positions of the tile's pixels lie in [8 t, 8 t + 8]; one pixel more each side.
    double px0 = double(tx * kTileSize) - 1.0, px1 = double(tx * kTileSize + kTileSize) + 1.0;
    double py0 = double(ty * kTileSize) - 1.0, py1 = double(ty * kTileSize + kTileSize) + 1.0;
    return {2.0 * px0 / width - 1.0, 2.0 * px1 / width - 1.0, 1.0 - 2.0 * py1 / height,
            1.0 - 2.0 * py0 / height};
}

struct RayFrame {
    glm::dvec3 eye, forward, du, dv;
    bool parallel;
};

std::array<glm::dvec3, 8> boxCorners(const SceneExtent &extent) {
    // Grown by a relative margin, so that rounding in the host's own arithmetic cannot cut it.
    glm::dvec3 pad = kEpsilon * (glm::abs(extent.boxMax - extent.boxMin) + glm::abs(extent.boxMin) +
                                 glm::abs(extent.boxMax)) +
                     1e-30;
    glm::dvec3 lo = extent.boxMin - pad, hi = extent.boxMax + pad;
    std::array<glm::dvec3, 8> corners;
    for (int k = 0; k < 8; ++k)
        corners[k] =
            glm::dvec3((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    return corners;
}

// Perspective: the tile's rays leave the eye inside the cone of its four corner directions.
// The box is missed when all its corners lie outside one of the cone's side planes, or behind
// the eye (every direction is forward plus a part across it, so the cone lies ahead).
bool coneMissesBox(const std::array<glm::dvec3, 4> &c, const std::array<glm::dvec3, 8> &corners,
                   const glm::dvec3 &eye, const glm::dvec3 &forward) {
    bool behind = true;
    for (const glm::dvec3 &p : corners)
        behind = behind && glm::dot(forward, p - eye) < 0.0;
    if (behind)
        return true;
    glm::dvec3 centre = c[0] + c[1] + c[2] + c[3];
    for (int j = 0; j < 4; ++j) {
        glm::dvec3 n = glm::cross(c[j], c[(j + 1) % 4]);
        if (glm::dot(n, centre) < 0.0)
            n = -n;
        bool allOutside = true;
        for (const glm::dvec3 &p : corners)
            allOutside = allOutside && glm::dot(n, p - eye) < 0.0;
        if (allOutside)
            return true;
    }
    return false;
}

// A ray o + t d (t > 0) hits the plane n.p = w where w - n.o and n.d have the same sign. The
// tile's rays miss it where every one has them of opposite signs, clearly: the shader's
// rounding could flip a sign that is nearly zero.
bool opposite(double g, double gScale, double s, double sScale) {
    return std::abs(g) > kEpsilon * gScale && std::abs(s) > kEpsilon * sScale && g * s < 0.0;
}

bool tileMayHit(const RayFrame &cam, const TileSpan &span, const SceneExtent &extent,
                const std::array<glm::dvec3, 8> &corners) {
    const double xs[2] = {span.x0, span.x1}, ys[2] = {span.y0, span.y1};
    if (!cam.parallel) {
        // Corner directions in order round the tile.
        std::array<glm::dvec3, 4> c = {cam.forward + xs[0] * cam.du + ys[0] * cam.dv,
                                       cam.forward + xs[1] * cam.du + ys[0] * cam.dv,
                                       cam.forward + xs[1] * cam.du + ys[1] * cam.dv,
                                       cam.forward + xs[0] * cam.du + ys[1] * cam.dv};
        if (extent.hasBox && !coneMissesBox(c, corners, cam.eye, cam.forward))
            return true;
        for (const glm::dvec4 &plane : extent.planes) {
            glm::dvec3 n(plane);
            double g = plane.w - glm::dot(n, cam.eye);
            double gScale = std::abs(plane.w) + glm::length(cam.eye);
            bool missed = true;
            for (const glm::dvec3 &d : c)
                missed = missed && opposite(g, gScale, glm::dot(n, d), glm::length(d));
            if (!missed)
                return true;
        }
        return false;
    }
    // Parallel: rays leave the image plane at eye + x du + y dv along forward. A point is hit
    // by the ray of its coordinates (a, b) in the basis (du, dv, forward), where c > 0.
    if (extent.hasBox) {
        glm::dmat3 toImage = glm::inverse(glm::dmat3(cam.du, cam.dv, cam.forward));
        bool left = true, right = true, below = true, above = true, behind = true;
        for (const glm::dvec3 &p : corners) {
            glm::dvec3 abc = toImage * (p - cam.eye);
            left = left && abc.x < span.x0;
            right = right && abc.x > span.x1;
            below = below && abc.y < span.y0;
            above = above && abc.y > span.y1;
            behind = behind && abc.z < 0.0;
        }
        if (!(left || right || below || above || behind))
            return true;
    }
    for (const glm::dvec4 &plane : extent.planes) {
        glm::dvec3 n(plane);
        double s = glm::dot(n, cam.forward);
        bool missed = true;
        for (double x : xs)
            for (double y : ys) {
                glm::dvec3 o = cam.eye + x * cam.du + y * cam.dv;
                missed = missed && opposite(plane.w - glm::dot(n, o),
                                            std::abs(plane.w) + glm::length(o), s, 1.0);
            }
        if (!missed)
            return true;
    }
    return false;
}

} // namespace

SceneExtent sceneExtent(const Scene &scene, const Grid &grid, bool hasFinite) {
    SceneExtent extent;
    extent.hasBox = hasFinite;
    extent.boxMin = glm::dvec3(grid.boundsMin);
    extent.boxMax = glm::dvec3(grid.boundsMax);
    for (const Plane &p : scene.planes) {
        glm::dvec3 n(p.normal);
        extent.planes.push_back(glm::dvec4(n, glm::dot(n, p.point)));
    }
    return extent;
}

TileRect tilesThatMayHit(const gpu::GpuFrameParams &frame, const SceneExtent &extent) {
    uint32_t width = frame.image.x, height = frame.image.y;
    TileRect image = imageTiles(width, height);
    // The camera as the shader has it: the frame's floats.
    RayFrame cam{glm::dvec3(frame.eye), glm::dvec3(frame.forward), glm::dvec3(frame.du),
                 glm::dvec3(frame.dv), gpu::isParallelCamera(frame)};
    std::array<glm::dvec3, 8> corners = boxCorners(extent);
    TileRect rect{image.x1, image.y1, 0, 0};
    for (uint32_t ty = 0; ty < image.y1; ++ty)
        for (uint32_t tx = 0; tx < image.x1; ++tx) {
            if (tx >= rect.x0 && tx < rect.x1 && ty >= rect.y0 && ty < rect.y1)
                continue; // already inside
            if (tileMayHit(cam, tileSpan(tx, ty, width, height), extent, corners)) {
                rect.x0 = std::min(rect.x0, tx);
                rect.y0 = std::min(rect.y0, ty);
                rect.x1 = std::max(rect.x1, tx + 1);
                rect.y1 = std::max(rect.y1, ty + 1);
            }
        }
    return rect.empty() ? TileRect{} : rect;
}

std::vector<TileRect> tilesAround(const TileRect &traced, const TileRect &image) {
    uint32_t tilesX = image.x1, tilesY = image.y1;
    if (traced.empty())
        return {image};
    std::vector<TileRect> rest = {{0, 0, tilesX, traced.y0},
                                  {0, traced.y1, tilesX, tilesY},
                                  {0, traced.y0, traced.x0, traced.y1},
                                  {traced.x1, traced.y0, tilesX, traced.y1}};
    rest.erase(
        std::remove_if(rest.begin(), rest.end(), [](const TileRect &r) { return r.empty(); }),
        rest.end());
    return rest;
}

} // namespace prism
