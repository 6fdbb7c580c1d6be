#include "scene/texture_loader.h"

#include "core/error.h"
#include "scene/text_file.h"

#include <system_error>

namespace prism {
namespace {

[[noreturn]] void failTexture(const std::filesystem::path &path, const std::string &why) {
    throw Error("cannot read texture '" + displayPath(path) + "': " + why);
}

} // namespace

int32_t TextureCache::load(const std::filesystem::path &path, Scene &scene, TexelMeaning meaning) {
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::canonical(path, ec);
    if (ec)
        failTexture(path, ec.message());
    // One file may be a colour texture and a bump map: two decodings, two entries.
    std::string key =
        canonical.string() + (meaning == TexelMeaning::Colour ? "\ncolour" : "\ndata");
    auto [it, inserted] = indexByCanonicalPath_.try_emplace(key, kNoTexture);
    if (!inserted)
        return it->second;
    try {
        scene.textures.push_back(readTexture(path, meaning));
    } catch (...) {
        indexByCanonicalPath_.erase(it);
        throw;
    }
    it->second = int32_t(scene.textures.size() - 1);
    return it->second;
}

} // namespace prism
