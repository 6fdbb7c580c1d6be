#pragma once
// Wavefront MTL reader for the statements a Whitted tracer can use. Mapping to a scene
// material: Kd -> color, mean of Ks -> specular, Ns -> shininess, Ni -> ior,
// Tr -> transmit, else 1 - d -> transmit, map_Kd -> texture, bump/map_Bump (with -bm) -> bump
// map, norm -> normal map. Everything else is ignored.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

struct MtlMaterial {
    std::string name;
    int line = 0; // of its newmtl
    std::optional<glm::vec3> kd;
    std::optional<glm::vec3> ks;
    std::optional<float> ns;
    std::optional<float> ni;
    std::optional<float> tr;
    std::optional<float> d;
    std::string texturePath; // map_Kd as written, backslashes turned into '/'; empty if none
    int textureLine = 0;
    std::string bumpPath; // bump or map_Bump, likewise
    int bumpLine = 0;
    float bumpScale = 1.0f; // its -bm
    std::string normalPath; // norm, likewise
    int normalLine = 0;
};

struct MtlLibrary {
    std::vector<MtlMaterial> materials;
    // The last definition of `name`, or nullptr.
    const MtlMaterial *find(std::string_view name) const;
};

// Parses MTL text. Keywords are matched case-insensitively. A malformed number is an error
// (prism::FileError at its line); a value a material cannot use (negative colour, Ni <= 0,
// d or Tr outside [0, 1], ...) and a name defined twice are warnings
// ("FILE:LINE: warning: ...", appended to `warnings`) and the value is not used.
MtlLibrary parseMtl(std::string_view text, const std::string &fileName,
                    std::vector<std::string> &warnings);

// The scene material for an MTL material: scene-material defaults where the MTL says nothing.
// The texture and maps are left to the caller (they must be loaded first).
Material materialFromMtl(const MtlMaterial &mtl, std::string sceneName);

} // namespace prism
