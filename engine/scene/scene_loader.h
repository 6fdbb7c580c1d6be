#pragma once
// Loading a scene: a .scene file (format v1, docs/scene-format.md) plus the OBJ, MTL and image
// files it names. Any problem throws; a scene is either loaded completely or not at all.
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "scene/obj_cache.h"
#include "scene/scene.h"

namespace prism {

// What one scene may hold, so that no file can make Prism allocate without bound (a scene can
// name one large OBJ file any number of times). Textures have their own limit
// (scene/texture_loader.h). Tests lower the limits to reach them.
struct SceneLimits {
    // 2^25 triangles: ~3.5 GB on the host, 1.5 GiB of vertices on the GPU. A prototype's
    // triangles (`mesh ... as`) count once, however often `place` draws them.
    uint64_t maxTriangles = uint64_t(1) << 25;
    // 2^22 instances (`place` lines), for memory: each takes 112 bytes on the GPU, 448 MiB at
    // the limit, and about as much again on the host; a line costs a few bytes of file.
    uint64_t maxInstances = uint64_t(1) << 22;
};

// Reads and parses `path`. Throws prism::FileError ("FILE:LINE: what is wrong") for errors in
// the scene or the files it names, a scene over `limits` among them, prism::Error when `path`
// itself cannot be read.
//
// With `objCache`, OBJ files of a megabyte or more are read back from its cache when they were
// parsed before, and stored when not (scene/obj_cache.h); it counts both.
Scene loadScene(const std::filesystem::path &path, const SceneLimits &limits = {},
                ObjCacheUse *objCache = nullptr);

// Parses scene text as if it had been read from `virtualPath` (used in messages); relative
// paths in it resolve against virtualPath's directory. Same errors as loadScene.
Scene parseScene(std::string_view text, const std::filesystem::path &virtualPath,
                 const SceneLimits &limits = {}, ObjCacheUse *objCache = nullptr);

} // namespace prism
