#pragma once
// The .scene reader's state while it walks one file, shared by the directive handlers.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "scene/mesh_importer.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene/texture_loader.h"
#include "scene/tokenizer.h"

namespace prism {

struct SceneBuilder {
    std::string fileName;          // as shown in messages
    std::filesystem::path baseDir; // relative paths resolve here
    int line = 0;                  // the line being parsed
    SceneLimits limits;

    Scene scene;
    // Names `use`, `sphere ... NAME` etc. may refer to: `default` and `material` lines only
    // (MTL materials are not reachable by name).
    std::unordered_map<std::string, uint32_t> materialByName;
    std::unordered_map<std::string, int> materialLine; // 0 for the built-in `default`
    uint32_t currentMaterial = 0;
    int cameraLine = 0;                  // 0 until a camera line
    int environmentLine = 0;             // 0 until an environment line
    std::vector<glm::dvec3> faceVertices; // this file's `v` lines, for `f`

    TextureCache textures;
    MeshImporter meshes;

    void warn(const std::string &message);
};

// Handles one non-empty line's tokens (keyword first). Throws LineError for problems of the
// line itself, prism::Error for files it cannot read, prism::FileError for errors inside them.
void applyDirective(SceneBuilder &builder, std::span<const Token> tokens);

// The parse behind parseScene (scene_loader.h).
Scene parseSceneText(std::string_view text, const std::filesystem::path &virtualPath,
                     const SceneLimits &limits);

} // namespace prism
