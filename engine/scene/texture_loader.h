#pragma once
// Texture images through OpenImageIO, decoded to linear RGBA floats, loaded once per file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>

#include "scene/scene.h"

namespace prism {

// The largest texture, in pixels (8192 x 8192): each is 16 bytes on the host and on the GPU,
// and an image header can claim any size, so a file is refused before its texels are
// allocated rather than making Prism allocate without bound.
constexpr uint64_t kMaxTexturePixels = uint64_t(1) << 26;

// What an image's values mean. Colour: 8- and 16-bit values are sRGB-encoded radiance. Data
// (normal and bump maps): they are numbers, scaled to [0, 1] and never sRGB-decoded, so a
// normal map's 128 stays 128/255.
enum class TexelMeaning { Colour, Data };

// Reads an image as a Texture: 8- and 16-bit images are sRGB-decoded for Colour (exact sRGB
// EOTF, alpha left linear) and only scaled to [0, 1] for Data; float images are taken as they
// are; grey, grey+alpha, RGB and RGBA become RGBA (alpha 1 where absent). Row 0 is the image's
// top row. Throws prism::Error ("cannot read texture 'PATH': reason"), also for an image over
// kMaxTexturePixels.
Texture readTexture(const std::filesystem::path &path, TexelMeaning meaning = TexelMeaning::Colour);

// sRGB-encoded value in [0, 1] to linear (IEC 61966-2-1 EOTF).
float srgbToLinear(float encoded);

// Scene::textures indices by canonical path and meaning, so a file named by several materials
// (or by several spellings of its path) is loaded once as colour and once as data at most.
class TextureCache {
public:
    // Index of `path`'s texture in scene.textures, loading it on first use. Throws like
    // readTexture.
    int32_t load(const std::filesystem::path &path, Scene &scene,
                 TexelMeaning meaning = TexelMeaning::Colour);

private:
    std::unordered_map<std::string, int32_t> indexByCanonicalPath_;
};

} // namespace prism
