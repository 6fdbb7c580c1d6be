#pragma once
// The .scene reader's state while it walks one file, shared by the directive handlers.
#include <cstdint>
#include <filesystem>
#include <optional>
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

// A prototype named by `mesh ... as ID`, as `place ID` needs it.
struct PrototypeEntry {
    std::optional<uint32_t> index; // into Scene::prototypes; none when it has no triangles
    glm::dvec3 centre{0.0};        // of the placed mesh's bounding box, taken off its vertices
    glm::dvec3 boxMin{0.0}, boxMax{0.0}; // its bounding box after centring
    int line = 0;                        // the `mesh ... as` line
};

// The last `place` line, which `key` lines under it move.
struct OpenPlacement {
    std::string prototype;
    PlacementTrack track; // its instance and keys; keys[0] is the place line's
    bool placed = false;  // false: the prototype has no triangles and nothing was placed
};

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
    int cameraLine = 0;                         // 0 until a camera line
    int environmentLine = 0;                    // 0 until an environment line
    int turntableLine = 0, interpolateLine = 0; // 0 until such a line
    // The directive a `key` line animates: "camera" or "place" when the last line other than a
    // key was one, else empty.
    std::string_view keyTarget;
    std::optional<OpenPlacement> lastPlace;
    std::vector<glm::dvec3> faceVertices; // this file's `v` lines, for `f`
    std::unordered_map<std::string, PrototypeEntry> prototypeByName;
    uint64_t prototypeTriangles = 0; // in all of Scene::prototypes

    // What counts against SceneLimits::maxTriangles: a prototype's triangles count once.
    uint64_t heldTriangles() const { return scene.triangles.size() + prototypeTriangles; }

    TextureCache textures;
    MeshImporter meshes;
    ObjCacheUse *objCache = nullptr; // where `mesh` lines' OBJ files are parsed or read back

    void warn(const std::string &message);
};

// Handles one non-empty line's tokens (keyword first). Throws LineError for problems of the
// line itself, prism::Error for files it cannot read, prism::FileError for errors inside them.
void applyDirective(SceneBuilder &builder, std::span<const Token> tokens);

// The parse behind parseScene (scene_loader.h).
Scene parseSceneText(std::string_view text, const std::filesystem::path &virtualPath,
                     const SceneLimits &limits, ObjCacheUse *objCache);

} // namespace prism
