#pragma once
// A mesh's placement: uniform scale, then rotations in the order written, then translation.
#include <vector>

#include <glm/glm.hpp>

namespace prism {

struct MeshRotation {
    int axis = 0;         // 0 = x, 1 = y, 2 = z
    double degrees = 0.0; // right-handed: counter-clockwise looking down the axis at the origin
};

struct MeshTransform {
    double scale = 1.0;
    std::vector<MeshRotation> rotations;
    glm::dvec3 translation{0.0};
};

// The transform as an affine map, in double precision so that composing it costs no accuracy.
class AffineMap {
public:
    explicit AffineMap(const MeshTransform &transform);
    glm::dvec3 point(glm::vec3 p) const { return linear_ * glm::dvec3(p) + offset_; }
    // Normals go through the inverse transpose (Phong normals stay perpendicular); not
    // normalised here.
    glm::dvec3 normal(glm::vec3 n) const { return normalMatrix_ * glm::dvec3(n); }

private:
    glm::dmat3 linear_{1.0};
    glm::dvec3 offset_{0.0};
    glm::dmat3 normalMatrix_{1.0};
};

// Rotation about a coordinate axis; quarter turns are exact (no cos(90°) = 6e-17 residue).
glm::dmat3 axisRotation(int axis, double degrees);

// The rotations in the order written, as one matrix: the last one written is the leftmost
// factor. AffineMap's linear part is this times the scale.
glm::dmat3 rotationOf(const std::vector<MeshRotation> &rotations);

// True when every component fits a 32-bit float (the GPU's positions).
bool fitsFloat(const glm::dvec3 &v);

} // namespace prism
