#pragma once
// An OBJ file big enough for the OBJ cache (scene/obj_cache.h, 1 MiB and more): a wavy field of
// n x n vertices with texture coordinates, two triangles a square.
#include <cmath>
#include <string>

namespace prism::test {

inline std::string wavyFieldObj(int n = 130) {
    std::string obj;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double x = i / double(n - 1), z = j / double(n - 1);
            obj += "v " + std::to_string(4 * x - 2) + " " +
                   std::to_string(0.3 * std::sin(9 * x) * std::cos(7 * z)) + " " +
                   std::to_string(4 * z - 2) + "\nvt " + std::to_string(x) + " " +
                   std::to_string(z) + "\n";
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            int a = j * n + i + 1, b = a + 1, c = a + n, d = c + 1;
            auto corner = [](int v) { return std::to_string(v) + "/" + std::to_string(v); };
            obj += "f " + corner(a) + " " + corner(c) + " " + corner(b) + "\nf " + corner(b) + " " +
                   corner(c) + " " + corner(d) + "\n";
        }
    return obj;
}

} // namespace prism::test
