#include "scene/vertex_normals.h"

#include <algorithm>
#include <cmath>

#include "core/parallel_for.h"

namespace prism {
namespace {

// Triangles a parallelFor index covers: enough that a block is worth a thread's turn.
constexpr size_t kBlock = 8192;

// The interior angle at corner c, from the edges to the other two corners.
double cornerAngle(const std::array<glm::dvec3, 3> &p, int c) {
    glm::dvec3 a = p[size_t((c + 1) % 3)] - p[size_t(c)];
    glm::dvec3 b = p[size_t((c + 2) % 3)] - p[size_t(c)];
    double la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0 && lb > 0.0))
        return 0.0;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

} // namespace

std::vector<std::array<glm::vec3, 3>>
smoothVertexNormals(std::span<const glm::dvec3> positions,
                    const std::vector<SmoothingTriangle> &triangles, double creaseDegrees) {
    size_t count = triangles.size();
    std::vector<glm::dvec3> facet(count);
    std::vector<std::array<double, 3>> angle(count);
    parallelForInBlocks(count, kBlock, [&](size_t i) {
        const std::array<uint32_t, 3> &v = triangles[i].vertex;
        std::array<glm::dvec3, 3> p = {positions[v[0]], positions[v[1]], positions[v[2]]};
        glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        double length = glm::length(n);
        facet[i] = length > 0.0 ? n / length : glm::dvec3(0.0);
        for (int c = 0; c < 3; ++c)
            angle[i][size_t(c)] = cornerAngle(p, c);
    });
    // Triangles around each vertex, as (triangle, corner) pairs in CSR form, each vertex's in
    // the triangles' order.
    std::vector<uint32_t> start(positions.size() + 1, 0);
    for (const SmoothingTriangle &t : triangles)
        for (uint32_t v : t.vertex)
            ++start[size_t(v) + 1];
    for (size_t v = 0; v < positions.size(); ++v)
        start[v + 1] += start[v];
    std::vector<std::pair<uint32_t, int>> around(start.back());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c)
            around[fill[triangles[i].vertex[size_t(c)]]++] = {uint32_t(i), c};

    // Facets meet at no more than the crease angle when their normals' cosine is at least this.
    double minCosine = std::cos(glm::radians(std::clamp(creaseDegrees, 0.0, 180.0)));
    std::vector<std::array<glm::vec3, 3>> normals(count);
    parallelForInBlocks(count, kBlock, [&](size_t i) {
        for (int c = 0; c < 3; ++c) {
            uint32_t v = triangles[i].vertex[size_t(c)];
            glm::dvec3 sum(0.0);
            for (uint32_t k = start[v]; k < start[size_t(v) + 1]; ++k) {
                auto [j, corner] = around[k];
                if (triangles[j].group != triangles[i].group ||
                    glm::dot(facet[j], facet[i]) < minCosine)
                    continue; // across a crease or a smoothing group: not this corner's surface
                sum += angle[j][size_t(corner)] * facet[j];
            }
            double length = glm::length(sum);
            // The corner's own facet always counts; only if it has no angle (a sliver) and its
            // neighbours cancel out is there no direction: then the facet's own normal.
            normals[i][size_t(c)] = glm::vec3(length > 0.0 ? sum / length : facet[i]);
        }
    });
    return normals;
}

} // namespace prism
