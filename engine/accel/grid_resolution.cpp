#include "accel/grid_resolution.h"

#include <algorithm>
#include <cmath>

namespace prism {

glm::ivec3 chooseResolution(const glm::dvec3 &extent, uint64_t primitiveCount, double density) {
    double targetCells = std::max(1.0, density * double(primitiveCount));
    targetCells = std::min(targetCells, double(kMaxGridCells));
    bool active[3] = {extent.x > 0.0, extent.y > 0.0, extent.z > 0.0};
    double side = 0.0;
    // Cube side s with prod(extent_i / s) = targetCells over the active axes; an active axis
    // shorter than s cannot hold even one cube, so it drops out and s is solved again.
    for (int pass = 0; pass < 3; ++pass) {
        int dims = 0;
        double measure = 1.0;
        for (int a = 0; a < 3; ++a)
            if (active[a]) {
                ++dims;
                measure *= extent[a];
            }
        if (dims == 0)
            return glm::ivec3(1);
        side = std::pow(measure / targetCells, 1.0 / dims);
        bool dropped = false;
        for (int a = 0; a < 3; ++a)
            if (active[a] && extent[a] < side) {
                active[a] = false;
                dropped = true;
            }
        if (!dropped)
            break;
    }
    glm::ivec3 res(1);
    for (int a = 0; a < 3; ++a)
        if (active[a] && side > 0.0)
            res[a] = int(std::clamp(std::round(extent[a] / side), 1.0, 256.0));
    return res;
}

} // namespace prism
