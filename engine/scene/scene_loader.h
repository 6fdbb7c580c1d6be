#pragma once
// Loading a scene: a .scene file (format v1, docs/scene-format.md) plus the OBJ, MTL and image
// files it names. Any problem throws; a scene is either loaded completely or not at all.
#include <filesystem>
#include <string_view>

#include "scene/scene.h"

namespace prism {

// Reads and parses `path`. Throws prism::FileError ("FILE:LINE: what is wrong") for errors in
// the scene or the files it names, prism::Error when `path` itself cannot be read.
Scene loadScene(const std::filesystem::path &path);

// Parses scene text as if it had been read from `virtualPath` (used in messages); relative
// paths in it resolve against virtualPath's directory. Same errors as loadScene.
Scene parseScene(std::string_view text, const std::filesystem::path &virtualPath);

} // namespace prism
