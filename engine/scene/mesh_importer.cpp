#include "scene/mesh_importer.h"

#include "core/error.h"
#include "core/huge_pages.h"
#include "scene/diagnostics.h"
#include "scene/text_file.h"
#include "scene/tokenizer.h"
#include "scene/vertex_normals.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <system_error>

namespace prism {
namespace {

bool isReadableFile(const std::filesystem::path &path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

// Placed vertex positions; a vertex pushed out of float range is an error of the mesh line.
std::vector<glm::dvec3> placePositions(const ObjModelView &model, const AffineMap &map) {
    std::vector<glm::dvec3> placed;
    reserveInHugePages(placed, model.positions.size());
    placed.resize(model.positions.size());
    for (size_t i = 0; i < placed.size(); ++i) {
        glm::dvec3 p = map.point(model.positions[i]);
        if (!fitsFloat(p))
            throw LineError("the mesh transform takes vertex " + std::to_string(i + 1) +
                            " out of the range of a 32-bit float");
        placed[i] = p;
    }
    return placed;
}

// Placed unit normals; a zero normal stays zero and disables vertex normals where it is used.
std::vector<glm::vec3> placeNormals(const ObjModelView &model, const AffineMap &map) {
    std::vector<glm::vec3> placed(model.normals.size());
    for (size_t i = 0; i < placed.size(); ++i) {
        glm::dvec3 n = map.normal(model.normals[i]);
        double length = glm::length(n);
        placed[i] = length > 0.0 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0);
    }
    return placed;
}

// For each vertex, the first vertex at the same position (itself if none before it), so that
// a file which repeats a vertex for each face (common after STL or per-face exports) still
// smooths across its faces. An open-addressing table on the coordinates' bits (-0 taken as
// +0, as the comparison of floats takes them): a std::map of 500,000 positions took 35 ms.
std::vector<uint32_t> weldedVertices(const ObjModelView &model) {
    auto bitsOf = [](float x) { return std::bit_cast<uint32_t>(x + 0.0f); }; // -0 + 0 is +0
    auto keyOf = [&](const glm::vec3 &p) {
        return std::array<uint32_t, 3>{bitsOf(p.x), bitsOf(p.y), bitsOf(p.z)};
    };
    size_t slots = std::bit_ceil(std::max<size_t>(2 * model.positions.size(), 16));
    constexpr uint32_t kEmpty = ~0u;
    std::vector<uint32_t> table(slots, kEmpty); // a vertex index, or empty
    std::vector<uint32_t> welded(model.positions.size());
    for (size_t i = 0; i < welded.size(); ++i) {
        std::array<uint32_t, 3> key = keyOf(model.positions[i]);
        uint64_t hash = (key[0] * 0x9E3779B97F4A7C15ull) ^ (key[1] * 0xC2B2AE3D27D4EB4Full) ^
                        (key[2] * 0x165667B19E3779F9ull);
        size_t slot = size_t(hash ^ (hash >> 29)) & (slots - 1);
        while (table[slot] != kEmpty && keyOf(model.positions[table[slot]]) != key)
            slot = (slot + 1) & (slots - 1);
        if (table[slot] == kEmpty)
            table[slot] = uint32_t(i);
        welded[i] = table[slot];
    }
    return welded;
}

} // namespace

bool hasZeroArea(const glm::dvec3 &p0, const glm::dvec3 &p1, const glm::dvec3 &p2) {
    return glm::cross(p1 - p0, p2 - p0) == glm::dvec3(0.0);
}

MeshImportResult MeshImporter::import(const ObjModelView &model, const MeshRequest &request,
                                      Scene &scene, TextureCache &textures,
                                      const TriangleSink &sink) {
    std::vector<uint32_t> slotMaterial;
    if (!request.namedMaterial)
        slotMaterial = slotMaterials(model, request, scene, textures);

    AffineMap map(request.transform);
    std::vector<glm::dvec3> positions = placePositions(model, map);
    std::vector<glm::vec3> normals = placeNormals(model, map);

    MeshImportResult result;
    std::vector<Triangle> triangles;
    std::vector<TriangleShading> shading;
    std::vector<SmoothingTriangle> shapes; // with `smooth`: one per triangle, for its normals
    std::vector<uint32_t> welded =
        request.smoothCreaseDegrees ? weldedVertices(model) : std::vector<uint32_t>{};
    // Sized once: growing a vector of a million triangles copied each of them about twice more
    // (issue 31).
    size_t fanTriangles = 0;
    for (const ObjFace &face : model.faces)
        fanTriangles += face.cornerCount - 2;
    if (sink.held < sink.maxTriangles) // no more than the limit lets in (checked below)
        fanTriangles = std::min<size_t>(fanTriangles, sink.maxTriangles - sink.held);
    reserveInHugePages(triangles, fanTriangles);
    // At most one record a triangle; smoothing gives every triangle one.
    if (request.smoothCreaseDegrees || !model.normals.empty() || !model.uvs.empty())
        reserveInHugePages(shading, fanTriangles);
    if (request.smoothCreaseDegrees)
        reserveInHugePages(shapes, fanTriangles);
    for (const ObjFace &face : model.faces) {
        uint32_t material = request.namedMaterial.value_or(request.fallbackMaterial);
        if (!request.namedMaterial && face.materialSlot != kObjNoIndex)
            material = slotMaterial[size_t(face.materialSlot)];
        const ObjCorner *corners = &model.corners[face.firstCorner];
        // Fan triangulation around the first corner.
        for (uint32_t k = 1; k + 1 < face.cornerCount; ++k) {
            const ObjCorner *tri[3] = {&corners[0], &corners[k], &corners[k + 1]};
            Triangle t;
            for (int c = 0; c < 3; ++c)
                t.p[c] = positions[size_t(tri[c]->position)];
            if (hasZeroArea(t.p[0], t.p[1], t.p[2])) {
                ++result.degenerateDropped;
                continue;
            }
            TriangleShading s;
            s.hasNormals = s.hasUVs = true;
            for (int c = 0; c < 3; ++c) {
                if (tri[c]->normal != kObjNoIndex)
                    s.n[c] = normals[size_t(tri[c]->normal)];
                s.hasNormals =
                    s.hasNormals && tri[c]->normal != kObjNoIndex && s.n[c] != glm::vec3(0.0f);
                if (tri[c]->uv != kObjNoIndex)
                    s.uv[c] = model.uvs[size_t(tri[c]->uv)];
                s.hasUVs = s.hasUVs && tri[c]->uv != kObjNoIndex;
            }
            if (!s.hasNormals)
                s.n[0] = s.n[1] = s.n[2] = glm::vec3(0.0f);
            if (!s.hasUVs)
                s.uv[0] = s.uv[1] = s.uv[2] = glm::vec2(0.0f);
            if (s.hasNormals || s.hasUVs) {
                t.shading = uint32_t(shading.size());
                shading.push_back(s);
            }
            t.material = material;
            checkTriangleLimit(sink.held + triangles.size() + 1, sink.maxTriangles);
            triangles.push_back(t);
            if (request.smoothCreaseDegrees)
                shapes.push_back(
                    {{welded[size_t(tri[0]->position)], welded[size_t(tri[1]->position)],
                      welded[size_t(tri[2]->position)]},
                     face.smoothingGroup});
        }
    }
    if (request.smoothCreaseDegrees) {
        // Triangles whose file gave normals keep them ("files with vn keep theirs").
        std::vector<std::array<glm::vec3, 3>> smooth =
            smoothVertexNormals(positions, shapes, *request.smoothCreaseDegrees);
        for (size_t i = 0; i < triangles.size(); ++i)
            if (TriangleShading &s = shadingFor(triangles[i], shading); !s.hasNormals) {
                for (int c = 0; c < 3; ++c)
                    s.n[c] = smooth[i][size_t(c)];
                s.hasNormals = true;
            }
    }
    result.triangles = triangles.size();
    if (sink.triangles.empty() && sink.shading.empty()) {
        sink.triangles = std::move(triangles);
        sink.shading = std::move(shading);
    } else {
        appendTriangles(sink.triangles, sink.shading, triangles, shading);
    }
    return result;
}

std::vector<uint32_t> MeshImporter::slotMaterials(const ObjModelView &model,
                                                  const MeshRequest &request, Scene &scene,
                                                  TextureCache &textures) {
    std::vector<const LoadedLibrary *> libraries = loadLibraries(model, request, scene);
    std::vector<bool> used(model.useMtl.size(), false);
    for (const ObjFace &face : model.faces)
        if (face.materialSlot != kObjNoIndex)
            used[size_t(face.materialSlot)] = true;

    std::string objDisplay = displayPath(request.objPath);
    std::vector<uint32_t> materials(model.useMtl.size(), request.fallbackMaterial);
    for (size_t slot = 0; slot < model.useMtl.size(); ++slot) {
        const ObjUseMtl &use = model.useMtl[slot];
        if (use.name.empty())
            continue;
        const LoadedLibrary *library = nullptr;
        const MtlMaterial *mtl = nullptr;
        for (auto it = libraries.rbegin(); it != libraries.rend() && !mtl; ++it) {
            mtl = (*it)->library.find(use.name);
            library = *it;
        }
        if (!mtl) {
            scene.warnings.push_back(warningAt(
                objDisplay, use.line,
                "material '" + use.name + "' is not defined in any mtllib file; its faces use '" +
                    scene.materials[request.fallbackMaterial].name + "'"));
            continue;
        }
        if (used[slot])
            materials[slot] = sceneMaterial(*library, *mtl, request, scene, textures);
    }
    return materials;
}

std::vector<const MeshImporter::LoadedLibrary *>
MeshImporter::loadLibraries(const ObjModelView &model, const MeshRequest &request, Scene &scene) {
    std::filesystem::path objDir = request.objPath.parent_path();
    std::string objDisplay = displayPath(request.objPath);
    std::vector<const LoadedLibrary *> libraries;
    std::vector<std::string_view> words;
    for (const ObjMtlLib &lib : model.mtlLibs) {
        // One name with spaces, or (as OBJ allows) several names separated by spaces.
        std::filesystem::path whole = resolveInputPath(objDir, lib.path);
        splitWords(lib.path, words);
        if (words.size() > 1 && !isReadableFile(whole)) {
            for (std::string_view word : words)
                if (const LoadedLibrary *loaded = loadLibrary(
                        resolveInputPath(objDir, std::string(word)), lib.line, objDisplay, scene))
                    libraries.push_back(loaded);
        } else if (const LoadedLibrary *loaded = loadLibrary(whole, lib.line, objDisplay, scene)) {
            libraries.push_back(loaded);
        }
    }
    return libraries;
}

const MeshImporter::LoadedLibrary *MeshImporter::loadLibrary(const std::filesystem::path &path,
                                                             int objLine,
                                                             const std::string &objDisplay,
                                                             Scene &scene) {
    std::string text;
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::canonical(path, ec);
    try {
        if (ec)
            throw Error("cannot read material library '" + displayPath(path) +
                        "': " + ec.message());
        auto found = librariesByCanonicalPath_.find(canonical.string());
        if (found != librariesByCanonicalPath_.end())
            return &found->second;
        text = readTextFile(path, "material library");
    } catch (const Error &e) {
        scene.warnings.push_back(warningAt(objDisplay, objLine, e.what()));
        return nullptr;
    }
    LoadedLibrary loaded{path, canonical.string(), displayPath(path), {}};
    loaded.library = parseMtl(text, loaded.display, scene.warnings);
    return &librariesByCanonicalPath_.emplace(canonical.string(), std::move(loaded)).first->second;
}

uint32_t MeshImporter::sceneMaterial(const LoadedLibrary &library, const MtlMaterial &mtl,
                                     const MeshRequest &request, Scene &scene,
                                     TextureCache &textures) {
    std::string key = library.canonical + '\n' + mtl.name;
    auto found = materialsByKey_.find(key);
    if (found != materialsByKey_.end())
        return found->second;

    Material material = materialFromMtl(mtl, request.objName + ":" + mtl.name);
    // An image that cannot be read is a warning at its MTL line, as a texture always was: the
    // material is still usable without it.
    auto loadMap = [&](const std::string &path, int line, TexelMeaning meaning) {
        if (path.empty())
            return kNoTexture;
        try {
            return textures.load(resolveInputPath(library.path.parent_path(), path), scene,
                                 meaning);
        } catch (const Error &e) {
            scene.warnings.push_back(warningAt(library.display, line,
                                               std::string(e.what()) + "; material '" + mtl.name +
                                                   "' is used without it"));
            return kNoTexture;
        }
    };
    material.texture = loadMap(mtl.texturePath, mtl.textureLine, TexelMeaning::Colour);
    material.bumpMap = loadMap(mtl.bumpPath, mtl.bumpLine, TexelMeaning::Data);
    material.normalMap = loadMap(mtl.normalPath, mtl.normalLine, TexelMeaning::Data);
    scene.materials.push_back(std::move(material));
    uint32_t index = uint32_t(scene.materials.size() - 1);
    materialsByKey_.emplace(std::move(key), index);
    return index;
}

} // namespace prism
