#include "scene/instance_flattening.h"

namespace prism {

MeshPrototype placedTriangles(const Scene &scene, const Instance &instance) {
    MeshPrototype placed = scene.prototypes.at(instance.prototype);
    for (Triangle &t : placed.triangles) {
        for (glm::dvec3 &p : t.p)
            p = instance.toWorld(p);
        if (instance.material != kOwnMaterials)
            t.material = uint32_t(instance.material);
    }
    // A similarity turns normals as it turns positions (no inverse transpose needed).
    for (TriangleShading &s : placed.shading)
        if (s.hasNormals)
            for (glm::vec3 &n : s.n)
                n = glm::vec3(glm::normalize(instance.rotation * glm::dvec3(n)));
    return placed;
}

Scene flattenInstances(Scene scene) {
    for (const Instance &instance : scene.instances) {
        MeshPrototype placed = placedTriangles(scene, instance);
        appendTriangles(scene.triangles, scene.triangleShading, placed.triangles, placed.shading);
    }
    scene.instances.clear();
    scene.prototypes.clear();
    scene.placementTracks.clear(); // the triangles stay where the instances are now
    return scene;
}

} // namespace prism
