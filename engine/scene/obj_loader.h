#pragma once
// Our own Wavefront OBJ reader: only what a ray tracer uses, every error at its OBJ line
// (tinyobjloader reports no line numbers and accepts NaN).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace prism {

constexpr int32_t kObjNoIndex = -1;

// One polygon corner, as 0-based indices into ObjModel's arrays.
struct ObjCorner {
    int32_t position = kObjNoIndex;
    int32_t uv = kObjNoIndex;
    int32_t normal = kObjNoIndex;
};

struct ObjFace {
    uint32_t firstCorner = 0;
    uint32_t cornerCount = 0;
    int32_t materialSlot = kObjNoIndex; // index into ObjModel::useMtl; none before any usemtl
    uint32_t smoothingGroup = 0;        // the `s` statement above it; 0 = off or none
    int line = 0;
};

struct ObjUseMtl {
    std::string name; // empty for a bare `usemtl`: back to the fallback material
    int line = 0;
};

struct ObjMtlLib {
    std::string path; // rest of the line, backslashes turned into '/'
    int line = 0;
};

struct ObjModelView;

struct ObjModel {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec3> normals;
    std::vector<ObjCorner> corners;
    std::vector<ObjFace> faces;
    std::vector<ObjUseMtl> useMtl;
    std::vector<ObjMtlLib> mtlLibs;
    // "FILE:LINE: warning: ..." lines, for Scene::warnings: at most one per kind of problem.
    std::vector<std::string> warnings;

    ObjModelView view() const;
};

// A model's arrays, viewed where they lie: in a parsed model's own vectors (ObjModel::view), or
// in a cache entry's mapped bytes (scene/obj_cache.h, LoadedObjModel). What the importer reads.
struct ObjModelView {
    std::span<const glm::vec3> positions;
    std::span<const glm::vec2> uvs;
    std::span<const glm::vec3> normals;
    std::span<const ObjCorner> corners;
    std::span<const ObjFace> faces;
    std::span<const ObjUseMtl> useMtl;
    std::span<const ObjMtlLib> mtlLibs;
    std::span<const std::string> warnings;
};
inline ObjModelView ObjModel::view() const {
    return {positions, uvs, normals, corners, faces, useMtl, mtlLibs, warnings};
}

// The viewed arrays copied into a model of their own.
ObjModel copyModel(const ObjModelView &view);

// Parses OBJ text. Reads v (extra w or colour values ignored), vt (u [v [w]]), vn, f (v, v/vt,
// v//vn, v/vt/vn; negative = relative to the last one defined), s (smoothing group: a number
// or `off`; anything else is group 0, warned once), usemtl and mtllib; ignores every other
// statement. An index must refer to an element defined above its face. Throws
// prism::FileError(fileName, line, ...) for a bad number, a bad index, a vertex index out of
// range, or a face with fewer than 3 corners. A texture-coordinate or normal index out of range
// (a file whose vt or vn lines were taken out; tinyobjloader and Blender load it) is not a
// geometry error: the corner goes without, and the first such index of each kind is a warning.
ObjModel parseObj(std::string_view text, const std::string &fileName);

} // namespace prism
