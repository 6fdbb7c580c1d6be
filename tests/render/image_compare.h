#pragma once
// Comparing a GPU image with the CPU reference, pixel by pixel.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace prism::test {

struct ImageDifference {
    size_t pixels = 0;
    size_t differing = 0;      // pixels whose largest channel difference exceeds the threshold
    double meanAbsolute = 0.0; // over all channels and pixels
    double largest = 0.0;
    size_t nonFinite = 0;
    double differingFraction() const { return pixels ? double(differing) / double(pixels) : 0.0; }
};

// `a` is RGBA floats; `b` is RGBA floats too. Alpha is ignored.
inline ImageDifference compareImages(const std::vector<float> &a, const std::vector<float> &b,
                                     double threshold) {
    ImageDifference d;
    d.pixels = std::min(a.size(), b.size()) / 4;
    double sum = 0.0;
    for (size_t p = 0; p < d.pixels; ++p) {
        double worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            double x = a[p * 4 + c], y = b[p * 4 + c];
            if (!std::isfinite(x) || !std::isfinite(y)) {
                d.nonFinite++;
                continue;
            }
            double diff = std::abs(x - y);
            sum += diff;
            worst = std::max(worst, diff);
        }
        d.largest = std::max(d.largest, worst);
        if (worst > threshold)
            d.differing++;
    }
    d.meanAbsolute = d.pixels ? sum / double(d.pixels * 3) : 0.0;
    return d;
}

inline std::string describe(const ImageDifference &d) {
    return std::to_string(d.differing) + "/" + std::to_string(d.pixels) +
           " pixels differ, mean abs " + std::to_string(d.meanAbsolute) + ", largest " +
           std::to_string(d.largest) + ", non-finite " + std::to_string(d.nonFinite);
}

} // namespace prism::test
