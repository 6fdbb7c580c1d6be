#pragma once
// Texture images through OpenImageIO, decoded to linear RGBA floats, loaded once per file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>

#include "scene/scene.h"

namespace prism {

// Reads an image as a Texture: 8- and 16-bit images are sRGB-decoded (exact sRGB EOTF, alpha
// left linear), float images are taken as they are; grey, grey+alpha, RGB and RGBA become RGBA
// (alpha 1 where absent). Row 0 is the image's top row. Throws prism::Error
// ("cannot read texture 'PATH': reason").
Texture readTexture(const std::filesystem::path &path);

// sRGB-encoded value in [0, 1] to linear (IEC 61966-2-1 EOTF).
float srgbToLinear(float encoded);

// Scene::textures indices by canonical path, so a file named by several materials (or by
// several spellings of its path) is loaded once.
class TextureCache {
public:
    // Index of `path`'s texture in scene.textures, loading it on first use. Throws like
    // readTexture.
    int32_t load(const std::filesystem::path &path, Scene &scene);

private:
    std::unordered_map<std::string, int32_t> indexByCanonicalPath_;
};

} // namespace prism
