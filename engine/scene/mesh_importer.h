#pragma once
// Turns a parsed OBJ into scene triangles: placement, fan triangulation, vertex normals and
// texture coordinates, MTL materials (loaded once per file) and their textures.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/mesh_transform.h"
#include "scene/mtl_loader.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"
#include "scene/texture_loader.h"

namespace prism {

struct MeshRequest {
    std::filesystem::path objPath; // resolved, for finding its MTL files
    std::string objName;           // as written on the mesh line: "<objName>:<mtl>"
    MeshTransform transform;
    std::optional<uint32_t> namedMaterial; // the mesh line's NAME: MTL files are not read
    uint32_t fallbackMaterial = 0;         // the current material
    // `smooth [ANGLE]`: vertex normals for triangles without, split at creases of more than
    // this many degrees (scene/vertex_normals.h).
    std::optional<double> smoothCreaseDegrees;
};

// Where a mesh's triangles go: the scene's own, or a prototype's (`mesh ... as`). Either way
// they count against the scene's triangle limit, on top of the `held` it has already.
struct TriangleSink {
    std::vector<Triangle> &triangles;
    std::vector<TriangleShading> &shading; // the records `triangles` point to
    uint64_t held = 0;                     // the scene's triangles and its prototypes'
    uint64_t maxTriangles = 0;             // SceneLimits::maxTriangles
};

struct MeshImportResult {
    size_t triangles = 0;         // added to the sink
    size_t degenerateDropped = 0; // zero-area triangles (they can never be hit)
};

class MeshImporter {
public:
    // Appends the model's triangles to `sink.triangles` (their normals and texture coordinates
    // to `sink.shading`), and the MTL materials and textures
    // they use to `scene`; MTL problems become warnings. Throws LineError if the transform
    // makes a vertex non-finite, or the scene would hold more than sink.maxTriangles triangles.
    MeshImportResult import(const ObjModelView &model, const MeshRequest &request, Scene &scene,
                            TextureCache &textures, const TriangleSink &sink);

private:
    struct LoadedLibrary {
        std::filesystem::path path;
        std::string canonical;
        std::string display;
        MtlLibrary library;
    };

    std::vector<const LoadedLibrary *> loadLibraries(const ObjModelView &model,
                                                     const MeshRequest &request, Scene &scene);
    const LoadedLibrary *loadLibrary(const std::filesystem::path &path, int objLine,
                                     const std::string &objDisplay, Scene &scene);
    std::vector<uint32_t> slotMaterials(const ObjModelView &model, const MeshRequest &request,
                                        Scene &scene, TextureCache &textures);
    uint32_t sceneMaterial(const LoadedLibrary &library, const MtlMaterial &mtl,
                           const MeshRequest &request, Scene &scene, TextureCache &textures);

    std::map<std::string, LoadedLibrary> librariesByCanonicalPath_;
    std::map<std::string, uint32_t> materialsByKey_; // canonical MTL path + '\n' + name
};

// True when the triangle has zero area: (p1 - p0) x (p2 - p0) == 0 in double arithmetic (the
// precision positions are kept in).
bool hasZeroArea(const glm::dvec3 &p0, const glm::dvec3 &p1, const glm::dvec3 &p2);

} // namespace prism
