#include "io/format_writers.h"
#include "io/oiio_metadata.h"
#include "io/oiio_output.h"
#include "io/srgb.h"

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace prism {
namespace {

// Shortest text that reads back as the same float (std::to_string keeps only 6 decimals).
std::string floatText(float value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

} // namespace

// 8-bit RGB. We encode to sRGB ourselves (exact OETF, round to nearest) and hand OIIO
// bytes, so no library conversion touches the values. Alpha is dropped: a render's alpha
// is coverage, and viewers would composite it over an arbitrary background.
void writePng(const std::filesystem::path &file, const OutputImage &image,
              const ImageMetadata &meta, const std::filesystem::path &reportedPath) {
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeUInt8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    // PNG keeps only text: floats and ints would be dropped by OIIO, so store them as text.
    ImageMetadata textual;
    textual.strings = meta.strings;
    for (const auto &[name, value] : meta.floats)
        textual.strings.emplace_back(name, floatText(value));
    for (const auto &[name, value] : meta.ints)
        textual.strings.emplace_back(name, std::to_string(value));
    addMetadata(spec, textual);

    const std::size_t pixelCount = static_cast<std::size_t>(image.width) * image.height;
    std::vector<std::uint8_t> bytes(pixelCount * 3);
    for (std::size_t i = 0; i < pixelCount; ++i)
        for (int k = 0; k < 3; ++k)
            bytes[i * 3 + k] = srgbEncode8(image.rgba[i * 4 + k]);
    writeWithOiio(file, "png", spec, bytes.data(), reportedPath);
}

} // namespace prism
