#include "scene/mesh_transform.h"

#include <cfloat>
#include <cmath>
#include <numbers>

namespace prism {
namespace {

// sin and cos of an angle in degrees, exact at multiples of 90.
void sinCosDegrees(double degrees, double &s, double &c) {
    double reduced = std::fmod(degrees, 360.0);
    if (reduced < 0)
        reduced += 360.0;
    if (std::fmod(reduced, 90.0) == 0.0) {
        static constexpr double kSin[4] = {0, 1, 0, -1};
        int quarter = int(reduced / 90.0) % 4;
        s = kSin[quarter];
        c = kSin[(quarter + 1) % 4];
        return;
    }
    double radians = reduced * std::numbers::pi / 180.0;
    s = std::sin(radians);
    c = std::cos(radians);
}

} // namespace

glm::dmat3 axisRotation(int axis, double degrees) {
    double s = 0, c = 1;
    sinCosDegrees(degrees, s, c);
    int a = (axis + 1) % 3, b = (axis + 2) % 3; // rotation in the (a, b) plane, a -> b
    glm::dmat3 m(1.0);                          // glm: m[column][row]
    m[a][a] = c;
    m[a][b] = s;
    m[b][a] = -s;
    m[b][b] = c;
    return m;
}

glm::dmat3 rotationOf(const std::vector<MeshRotation> &rotations) {
    glm::dmat3 m(1.0);
    for (const MeshRotation &rotation : rotations)
        m = axisRotation(rotation.axis, rotation.degrees) * m;
    return m;
}

bool fitsFloat(const glm::dvec3 &v) {
    return std::fabs(v.x) <= FLT_MAX && std::fabs(v.y) <= FLT_MAX && std::fabs(v.z) <= FLT_MAX;
}

AffineMap::AffineMap(const MeshTransform &transform) {
    linear_ = rotationOf(transform.rotations) * transform.scale;
    offset_ = transform.translation;
    normalMatrix_ = glm::transpose(glm::inverse(linear_));
}

} // namespace prism
