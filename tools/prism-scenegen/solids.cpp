#include "solids.h"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace prism::scenegen {
namespace {

// Turns each face of a solid that is star-shaped about `centre` to face away from it.
void orientOutward(Solid &solid, const glm::dvec3 &centre) {
    for (auto &f : solid.faces) {
        const glm::dvec3 &a = solid.vertices[f[0]], &b = solid.vertices[f[1]],
                         &c = solid.vertices[f[2]];
        glm::dvec3 normal = glm::cross(b - a, c - a);
        if (glm::dot(normal, (a + b + c) / 3.0 - centre) < 0.0)
            std::swap(f[1], f[2]);
    }
}

} // namespace

Solid tetrahedron(double edge) {
    double base = edge / std::sqrt(3.0);         // circumradius of the base triangle
    double height = edge * std::sqrt(2.0 / 3.0); // apex above the base
    Solid s;
    for (int i = 0; i < 3; ++i) {
        double angle = 2.0 * std::numbers::pi * i / 3.0;
        s.vertices.push_back({base * std::sin(angle), 0.0, base * std::cos(angle)});
    }
    s.vertices.push_back({0.0, height, 0.0});
    s.faces = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    orientOutward(s, {0.0, height / 4.0, 0.0});
    return s;
}

Solid octahedron(double radius) {
    Solid s;
    s.vertices = {{radius, 0, 0},  {-radius, 0, 0}, {0, radius, 0},
                  {0, -radius, 0}, {0, 0, radius},  {0, 0, -radius}};
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5})
                s.faces.push_back({x, y, z});
    orientOutward(s, glm::dvec3(0.0));
    return s;
}

Solid box(const glm::dvec3 &size) {
    Solid s;
    glm::dvec3 h = size / 2.0;
    for (int i = 0; i < 8; ++i)
        s.vertices.push_back({i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z});
    // Each side as two triangles over corner indices (bit 0 = +x, bit 1 = +y, bit 2 = +z).
    static constexpr int kSides[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                         {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto &q : kSides) {
        s.faces.push_back({q[0], q[1], q[2]});
        s.faces.push_back({q[0], q[2], q[3]});
    }
    orientOutward(s, glm::dvec3(0.0));
    return s;
}

Solid icosphere(double radius, int levels) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Solid s;
    s.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    s.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (glm::dvec3 &v : s.vertices)
        v = glm::normalize(v);
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> midpoints;
        auto midpoint = [&](int a, int b) {
            std::pair<int, int> key{std::min(a, b), std::max(a, b)};
            auto found = midpoints.find(key);
            if (found != midpoints.end())
                return found->second;
            s.vertices.push_back(glm::normalize(s.vertices[a] + s.vertices[b]));
            int index = int(s.vertices.size()) - 1;
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<std::array<int, 3>> finer;
        for (const auto &f : s.faces) {
            int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        s.faces = std::move(finer);
    }
    for (glm::dvec3 &v : s.vertices)
        v *= radius;
    orientOutward(s, glm::dvec3(0.0));
    return s;
}

Solid torus(double majorRadius, double minorRadius, int majorSegments, int minorSegments) {
    Solid s;
    auto index = [&](int i, int j) {
        return (i % majorSegments) * minorSegments + (j % minorSegments);
    };
    for (int i = 0; i < majorSegments; ++i) {
        double u = 2.0 * std::numbers::pi * i / majorSegments;
        for (int j = 0; j < minorSegments; ++j) {
            double v = 2.0 * std::numbers::pi * j / minorSegments;
            double ring = majorRadius + minorRadius * std::cos(v);
            s.vertices.push_back(
                {ring * std::cos(u), minorRadius * std::sin(v), ring * std::sin(u)});
        }
    }
    for (int i = 0; i < majorSegments; ++i)
        for (int j = 0; j < minorSegments; ++j) {
            int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
            s.faces.push_back({a, b, c});
            s.faces.push_back({a, c, d});
        }
    // Each face must point away from the tube's centre circle at its own angle.
    for (auto &f : s.faces) {
        const glm::dvec3 &a = s.vertices[f[0]], &b = s.vertices[f[1]], &c = s.vertices[f[2]];
        glm::dvec3 centroid = (a + b + c) / 3.0;
        glm::dvec3 radial = glm::normalize(glm::dvec3(centroid.x, 0.0, centroid.z));
        glm::dvec3 tubeCentre = radial * majorRadius;
        if (glm::dot(glm::cross(b - a, c - a), centroid - tubeCentre) < 0.0)
            std::swap(f[1], f[2]);
    }
    return s;
}

Solid quad(const glm::dvec3 &u, const glm::dvec3 &v) {
    Solid s;
    s.vertices = {-0.5 * u - 0.5 * v, 0.5 * u - 0.5 * v, 0.5 * u + 0.5 * v, -0.5 * u + 0.5 * v};
    s.faces = {{0, 1, 2}, {0, 2, 3}};
    return s;
}

Solid placed(Solid solid, double scale, double yDegrees, const glm::dvec3 &translation) {
    double radians = yDegrees * std::numbers::pi / 180.0;
    double c = std::cos(radians), s = std::sin(radians);
    for (glm::dvec3 &p : solid.vertices) {
        glm::dvec3 q = p * scale;
        p = glm::dvec3(c * q.x + s * q.z, q.y, -s * q.x + c * q.z) + translation;
    }
    return solid;
}

Solid rotatedX(Solid solid, double degrees) {
    double radians = degrees * std::numbers::pi / 180.0;
    double c = std::cos(radians), s = std::sin(radians);
    for (glm::dvec3 &p : solid.vertices) // y -> z for positive angles, as `rotate x`
        p = glm::dvec3(p.x, c * p.y - s * p.z, s * p.y + c * p.z);
    return solid;
}

void writeSolid(SceneText &out, const Solid &solid, const std::string &material) {
    out.line("use " + material);
    for (const glm::dvec3 &v : solid.vertices)
        out.line("v " + formatVec(v));
    const int count = int(solid.vertices.size());
    for (const auto &f : solid.faces)
        out.line("f " + std::to_string(f[0] - count) + " " + std::to_string(f[1] - count) + " " +
                 std::to_string(f[2] - count));
}

} // namespace prism::scenegen
