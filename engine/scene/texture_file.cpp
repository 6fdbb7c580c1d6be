// Decoding a texture file (scene/texture_loader.h: readTexture) through OpenImageIO: built
// into prism_oiio, the library of everything that calls OpenImageIO (engine/io/CMakeLists.txt).
#include "scene/texture_loader.h"

#include "core/error.h"

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <memory>

namespace prism {
namespace {

// scene/text_file.h's displayPath: this library does not link the scene's.
std::string displayPath(const std::filesystem::path &path) {
    return path.lexically_normal().generic_string();
}


[[noreturn]] void failTexture(const std::filesystem::path &path, const std::string &why) {
    throw Error("cannot read texture '" + displayPath(path) + "': " + why);
}

// IEC 61966-2-1 sRGB EOTF, in double so 8-bit values decode to the correctly rounded float.
double srgbEotf(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

const std::array<float, 256> &srgb8ToLinear() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> values{};
        for (int i = 0; i < 256; ++i)
            values[i] = float(srgbEotf(i / 255.0));
        return values;
    }();
    return table;
}

bool isFloatFormat(OIIO::TypeDesc format) {
    return format.basetype == OIIO::TypeDesc::HALF || format.basetype == OIIO::TypeDesc::FLOAT ||
           format.basetype == OIIO::TypeDesc::DOUBLE;
}

// Expands `channels` values per pixel to RGBA: grey -> (g, g, g), grey+alpha, RGB, RGBA
// (channels past the fourth are dropped). `colour` decodes colour values, `alpha` only
// normalises (alpha is never sRGB-encoded).
template <typename T, typename Colour, typename Alpha>
void toRgba(const std::vector<T> &pixels, int channels, Colour colour, Alpha alpha,
            Texture &texture) {
    size_t count = size_t(texture.width) * size_t(texture.height);
    texture.texels.resize(count);
    for (size_t p = 0; p < count; ++p) {
        const T *in = &pixels[p * size_t(channels)];
        glm::vec4 &out = texture.texels[p];
        if (channels <= 2)
            out = glm::vec4(glm::vec3(colour(in[0])), 1.0f);
        else
            out = glm::vec4(colour(in[0]), colour(in[1]), colour(in[2]), 1.0f);
        if (channels == 2)
            out.a = alpha(in[1]);
        else if (channels >= 4)
            out.a = alpha(in[3]);
    }
}

} // namespace

float srgbToLinear(float encoded) {
    return float(srgbEotf(encoded));
}

Texture readTexture(const std::filesystem::path &path, TexelMeaning meaning) {
    // Keep straight (unassociated) alpha: colour must not come back premultiplied.
    OIIO::ImageSpec hints;
    hints.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string(), &hints);
    if (!in)
        failTexture(path, OIIO::geterror());
    const OIIO::ImageSpec &spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
        failTexture(path, "not a 2D image");
    uint64_t pixels = uint64_t(spec.width) * uint64_t(spec.height);
    if (pixels > kMaxTexturePixels || spec.nchannels > 64)
        failTexture(
            path, std::to_string(spec.width) + " x " + std::to_string(spec.height) + " pixels of " +
                      std::to_string(spec.nchannels) + " channels is more than a texture may be (" +
                      std::to_string(kMaxTexturePixels) + " pixels, 8192 x 8192, and 64 channels)");

    Texture texture;
    texture.path = displayPath(path);
    texture.width = spec.width;
    texture.height = spec.height;
    int channels = spec.nchannels;
    size_t values = size_t(spec.width) * size_t(spec.height) * size_t(channels);
    bool read = false;
    bool colour = meaning == TexelMeaning::Colour;
    if (isFloatFormat(spec.format)) {
        std::vector<float> pixels(values);
        read = in->read_image(0, 0, 0, channels, OIIO::TypeFloat, pixels.data());
        if (read)
            toRgba(
                pixels, channels, [](float v) { return v; }, [](float v) { return v; }, texture);
    } else if (spec.format.size() == 1) {
        std::vector<uint8_t> pixels(values);
        read = in->read_image(0, 0, 0, channels, OIIO::TypeUInt8, pixels.data());
        if (read)
            toRgba(
                pixels, channels,
                [colour](uint8_t v) { return colour ? srgb8ToLinear()[v] : float(v) / 255.0f; },
                [](uint8_t v) { return float(v) / 255.0f; }, texture);
    } else {
        std::vector<uint16_t> pixels(values);
        read = in->read_image(0, 0, 0, channels, OIIO::TypeUInt16, pixels.data());
        if (read)
            toRgba(
                pixels, channels,
                [colour](uint16_t v) {
                    return colour ? float(srgbEotf(v / 65535.0)) : float(v) / 65535.0f;
                },
                [](uint16_t v) { return float(v) / 65535.0f; }, texture);
    }
    if (!read)
        failTexture(path, in->geterror());
    in->close();
    return texture;
}

} // namespace prism
