#include "scene/instance_flattening.h"

namespace prism {

std::vector<Triangle> placedTriangles(const Scene &scene, const Instance &instance) {
    std::vector<Triangle> placed = scene.prototypes.at(instance.prototype).triangles;
    for (Triangle &t : placed) {
        for (int c = 0; c < 3; ++c) {
            t.p[c] = instance.toWorld(t.p[c]);
            // A similarity turns normals as it turns positions (no inverse transpose needed).
            if (t.hasNormals)
                t.n[c] = glm::vec3(glm::normalize(instance.rotation * glm::dvec3(t.n[c])));
        }
        if (instance.material != kOwnMaterials)
            t.material = uint32_t(instance.material);
    }
    return placed;
}

Scene flattenInstances(Scene scene) {
    for (const Instance &instance : scene.instances) {
        std::vector<Triangle> placed = placedTriangles(scene, instance);
        scene.triangles.insert(scene.triangles.end(), placed.begin(), placed.end());
    }
    scene.instances.clear();
    scene.prototypes.clear();
    scene.placementTracks.clear(); // the triangles stay where the instances are now
    return scene;
}

} // namespace prism
