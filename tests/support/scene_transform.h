#pragma once
// The same scene at another scale or place, for tests that the picture does not depend on
// either.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::test {

// Every position and length scaled by `scale` then moved by `offset`; directions and colours
// unchanged. With the default offset positions are only scaled: adding 0 changes no value.
inline Scene transformed(Scene scene, double scale, glm::dvec3 offset = glm::dvec3(0.0)) {
    auto move = [&](glm::dvec3 p) { return p * scale + offset; };
    scene.camera.eye = move(scene.camera.eye);
    scene.camera.look = move(scene.camera.look);
    scene.camera.orthoHeight *= float(scale); // 0 (perspective) stays 0
    for (Light &l : scene.lights) {
        l.position = move(l.position);
        l.radius *= float(scale);
    }
    for (Sphere &s : scene.spheres) {
        s.center = move(s.center);
        s.radius *= float(scale);
    }
    for (Plane &p : scene.planes)
        p.point = move(p.point);
    for (Triangle &t : scene.triangles)
        for (glm::dvec3 &p : t.p)
            p = move(p);
    for (Instance &i : scene.instances) { // prototypes stay in their own space
        i.translation = move(i.translation);
        i.scale *= scale;
    }
    return scene;
}

} // namespace prism::test
