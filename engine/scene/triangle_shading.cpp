#include "scene/scene.h"

namespace prism {

void appendTriangles(std::vector<Triangle> &to, std::vector<TriangleShading> &toShading,
                     std::span<const Triangle> from, std::span<const TriangleShading> fromShading) {
    size_t first = to.size();
    to.insert(to.end(), from.begin(), from.end());
    // Records are appended in the order their triangles first name them; a record two
    // triangles share (none do today) would be copied once for each.
    for (size_t i = first; i < to.size(); ++i)
        if (Triangle &t = to[i]; t.shading != kNoShading) {
            toShading.push_back(fromShading[t.shading]);
            t.shading = uint32_t(toShading.size() - 1);
        }
}

} // namespace prism
