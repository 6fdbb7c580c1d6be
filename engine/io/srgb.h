#pragma once
// Exact piecewise sRGB transfer functions (IEC 61966-2-1), shared by the PNG writer, tests
// and tools, so every 8-bit image Prism writes is encoded the same way.
#include <cmath>
#include <cstdint>

namespace prism {

// Linear -> sRGB-encoded; no clamping (values outside [0, 1] extend the curve).
inline float srgbEncode(float linear) {
    if (linear <= 0.0031308f)
        return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// sRGB-encoded -> linear; the inverse of srgbEncode.
inline float srgbDecode(float encoded) {
    if (encoded <= 0.04045f)
        return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

// Linear -> 8-bit sRGB code: clamp to [0, 1] (NaN -> 0), encode, round to nearest.
inline std::uint8_t srgbEncode8(float linear) {
    if (!(linear > 0.0f))
        return 0;
    if (linear >= 1.0f)
        return 255;
    return static_cast<std::uint8_t>(std::lround(srgbEncode(linear) * 255.0f));
}

} // namespace prism
