#include "accel/overlap_tests.h"

#include <algorithm>
#include <cmath>

namespace prism {

bool sphereOverlapsBox(const glm::dvec3 &center, double radius, const glm::dvec3 &boxMin,
                       const glm::dvec3 &boxMax) {
    glm::dvec3 nearest = glm::clamp(center, boxMin, boxMax);
    glm::dvec3 d = center - nearest;
    return glm::dot(d, d) <= radius * radius;
}

namespace {

// Projects the triangle (relative to the box centre) and the box onto `axis`; true when the
// two intervals are disjoint. A zero axis (parallel edges) separates nothing.
bool separatedOnAxis(const glm::dvec3 &axis, const glm::dvec3 (&v)[3], const glm::dvec3 &half) {
    double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
    double r = half.x * std::abs(axis.x) + half.y * std::abs(axis.y) + half.z * std::abs(axis.z);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

} // namespace

bool triangleOverlapsBox(const glm::dvec3 &p0, const glm::dvec3 &p1, const glm::dvec3 &p2,
                         const glm::dvec3 &boxMin, const glm::dvec3 &boxMax) {
    // A vertex inside the box settles it, exactly and at once: the common case for the small
    // triangles of a dense mesh against the cells that list them.
    for (const glm::dvec3 *p : {&p0, &p1, &p2})
        if (glm::all(glm::greaterThanEqual(*p, boxMin)) && glm::all(glm::lessThanEqual(*p, boxMax)))
            return true;
    glm::dvec3 center = 0.5 * (boxMin + boxMax), half = 0.5 * (boxMax - boxMin);
    const glm::dvec3 v[3] = {p0 - center, p1 - center, p2 - center};
    // Box face normals: the triangle's bounding box against the box.
    for (int a = 0; a < 3; ++a) {
        double lo = std::min({v[0][a], v[1][a], v[2][a]});
        double hi = std::max({v[0][a], v[1][a], v[2][a]});
        if (lo > half[a] || hi < -half[a])
            return false;
    }
    const glm::dvec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    // The triangle's plane.
    if (separatedOnAxis(glm::cross(edges[0], edges[1]), v, half))
        return false;
    // Edge x box-axis cross products: e x unit(a) has a zero in coordinate a and (e[b], -e[c])
    // in the two others (b, c the axes after a), so each projection is two products. The same
    // values as the general dot product: the zero term adds nothing, in floating point too.
    for (const glm::dvec3 &e : edges)
        for (int a = 0; a < 3; ++a) {
            int b = (a + 1) % 3, c = (a + 2) % 3;
            double p0 = e[c] * v[0][b] - e[b] * v[0][c];
            double p1 = e[c] * v[1][b] - e[b] * v[1][c];
            double p2 = e[c] * v[2][b] - e[b] * v[2][c];
            double r = half[b] * std::abs(e[c]) + half[c] * std::abs(e[b]);
            if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r)
                return false;
        }
    return true;
}

} // namespace prism
