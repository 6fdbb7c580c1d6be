#pragma once
// Axis-aligned boxes in double precision, for building the grid.
#include <algorithm>
#include <limits>

#include <glm/glm.hpp>

namespace prism {

struct Aabb {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void grow(const glm::dvec3 &p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Aabb &b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    glm::dvec3 extent() const { return max - min; }
};

} // namespace prism
