#include "scene_edit.h"

#include <algorithm>
#include <cstdio>

#include <glm/glm.hpp>

namespace prism {

std::string sceneVariant(const std::string &text, const Camera &camera, uint32_t variant) {
    std::string out = text;
    uint32_t spheres = variant % kSceneVariants;
    if (spheres == 0)
        return out;
    if (!out.empty() && out.back() != '\n')
        out += '\n';
    out += "# added by prism-view's soak run\n";
    glm::vec3 view(camera.look - camera.eye);
    float distance = glm::length(view);
    glm::vec3 side = glm::cross(view, camera.up);
    side = glm::length(side) > 0.0f ? glm::normalize(side) : glm::vec3(1.0f, 0.0f, 0.0f);
    float radius = std::max(0.04f * distance, 1e-3f); // a scene's radius must be > 0
    for (uint32_t i = 0; i < spheres; ++i) {
        // Left and right of the look point, a quarter of the distance out.
        glm::dvec3 centre =
            camera.look + glm::dvec3(side * (i % 2 == 0 ? 0.25f : -0.25f) * distance);
        char line[160];
        std::snprintf(line, sizeof line, "sphere %.17g %.17g %.17g %.6g default\n", centre.x,
                      centre.y, centre.z, double(radius));
        out += line;
    }
    return out;
}

} // namespace prism
