#include "scene/placement.h"

#include "scene/number_parser.h"

namespace prism {

Instance placedInstance(const MeshTransform &transform, const glm::dvec3 &centre) {
    Instance instance;
    instance.scale = transform.scale;
    instance.rotation = rotationOf(transform.rotations);
    instance.translation =
        transform.translation + transform.scale * (instance.rotation * centre);
    return instance;
}

std::string placementProblem(const Instance &instance, const glm::dvec3 &boxMin,
                             const glm::dvec3 &boxMax, const std::string &name) {
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 p((corner & 1) ? boxMax.x : boxMin.x, (corner & 2) ? boxMax.y : boxMin.y,
                     (corner & 4) ? boxMax.z : boxMin.z);
        if (!fitsFloat(instance.toWorld(p)))
            return "the placement takes the bounding box of prototype '" + name +
                   "' out of the range of a 32-bit float";
    }
    // The tracer takes rays into the prototype's space by the inverse map (1 / scale, and the
    // translation over the scale), in 32-bit floats too.
    if (!fitsFloat(glm::dvec3(1.0 / instance.scale)) ||
        !fitsFloat(instance.translation / instance.scale))
        return "'scale' " + formatNumber(instance.scale) +
               " is too small for the placement to be undone in 32-bit floats";
    return "";
}

} // namespace prism
