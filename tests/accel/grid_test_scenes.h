#pragma once
// Random scenes of spheres and triangles for the grid tests.
#include <random>

#include "scene/scene.h"

namespace prism::test {

inline Scene randomSpheresAndTriangles(unsigned seed, int spheres, int triangles,
                                       double size = 10.0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coord(-size, size), unit(0.0, 1.0);
    Scene scene;
    for (int i = 0; i < spheres; ++i) {
        Sphere s;
        s.center = glm::vec3(coord(rng), coord(rng), coord(rng));
        s.radius = float(size * (0.01 + 0.1 * unit(rng)));
        scene.spheres.push_back(s);
    }
    for (int i = 0; i < triangles; ++i) {
        Triangle t;
        glm::dvec3 base(coord(rng), coord(rng), coord(rng));
        double extent = size * (unit(rng) < 0.1 ? 1.0 : 0.15); // a few large ones
        for (glm::vec3 &p : t.p)
            p = glm::vec3(base +
                          extent * glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        scene.triangles.push_back(t);
    }
    return scene;
}

} // namespace prism::test
