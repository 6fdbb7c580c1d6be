#pragma once
// Colour helpers for generated materials.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace prism::scenegen {

// HSV (hue in degrees, saturation and value in [0, 1]) to linear RGB. Only + - * / and fmod,
// all exactly rounded in IEEE arithmetic, so every machine gets the same bits.
inline glm::dvec3 hsvToRgb(double hueDegrees, double saturation, double value) {
    double h = std::fmod(hueDegrees, 360.0) / 60.0;
    int sector = std::min(5, int(h));
    double f = h - sector;
    double p = value * (1.0 - saturation);
    double q = value * (1.0 - saturation * f);
    double t = value * (1.0 - saturation * (1.0 - f));
    switch (sector) {
    case 0:
        return {value, t, p};
    case 1:
        return {q, value, p};
    case 2:
        return {p, value, t};
    case 3:
        return {p, q, value};
    case 4:
        return {t, p, value};
    default:
        return {value, p, q};
    }
}

} // namespace prism::scenegen
