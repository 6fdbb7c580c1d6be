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
    size_t nonFinite = 0; // channels that are NaN or infinite in either image (each differs)
    // The images are not comparable (different or no sizes): every pixel counts as differing,
    // so that an empty or truncated readback fails every bound instead of passing them all.
    bool sizesDiffer = false;
    double differingFraction() const { return pixels ? double(differing) / double(pixels) : 0.0; }
};

// `a` and `b` are RGBA floats; alpha is ignored. Pixels where `skip` is true are not compared.
inline ImageDifference compareImages(const std::vector<float> &a, const std::vector<float> &b,
                                     double threshold, const std::vector<bool> &skip = {}) {
    ImageDifference d;
    if (a.size() != b.size() || a.empty() || a.size() % 4 != 0) {
        d.sizesDiffer = true;
        d.pixels = d.differing = std::max<size_t>(1, std::max(a.size(), b.size()) / 4);
        d.meanAbsolute = d.largest = HUGE_VAL;
        return d;
    }
    size_t count = a.size() / 4;
    double sum = 0.0;
    for (size_t p = 0; p < count; ++p) {
        if (!skip.empty() && skip[p])
            continue;
        d.pixels++;
        double worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            double x = a[p * 4 + c], y = b[p * 4 + c];
            double diff = std::abs(x - y);
            if (!std::isfinite(x) || !std::isfinite(y)) {
                // A NaN or infinity is never a match: the pixel differs by any threshold, and
                // where the other image is finite the mean becomes infinite, failing every bound
                // on it (a comparison that let a NaN image through was testing nothing).
                d.nonFinite++;
                bool oneSided = std::isfinite(x) != std::isfinite(y);
                worst = HUGE_VAL;
                if (oneSided)
                    sum += HUGE_VAL;
                continue;
            }
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

// Pixels within `radius` of a place where the image changes by more than `contrast` between
// neighbours: silhouettes and shadow edges, where a sub-pixel shift of geometry legitimately
// changes a pixel. Flat regions (where acne and lost shadows would show) stay unmasked.
inline std::vector<bool> edgeBand(const std::vector<float> &rgba, int width, int height, int radius,
                                  float contrast) {
    auto at = [&](int x, int y, int c) { return rgba[(size_t(y) * width + x) * 4 + c]; };
    std::vector<bool> edge(size_t(width) * height, false);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                if (x + 1 < width && std::abs(at(x, y, c) - at(x + 1, y, c)) > contrast)
                    edge[size_t(y) * width + x] = edge[size_t(y) * width + x + 1] = true;
                if (y + 1 < height && std::abs(at(x, y, c) - at(x, y + 1, c)) > contrast)
                    edge[size_t(y) * width + x] = edge[size_t(y + 1) * width + x] = true;
            }
    std::vector<bool> band(edge.size(), false);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!edge[size_t(y) * width + x])
                continue;
            for (int dy = -radius; dy <= radius; ++dy)
                for (int dx = -radius; dx <= radius; ++dx) {
                    int nx = x + dx, ny = y + dy;
                    if (nx >= 0 && ny >= 0 && nx < width && ny < height)
                        band[size_t(ny) * width + nx] = true;
                }
        }
    return band;
}

inline std::string describe(const ImageDifference &d) {
    if (d.sizesDiffer)
        return "the images differ in size (or are empty): nothing to compare";
    return std::to_string(d.differing) + "/" + std::to_string(d.pixels) +
           " pixels differ, mean abs " + std::to_string(d.meanAbsolute) + ", largest " +
           std::to_string(d.largest) + ", non-finite " + std::to_string(d.nonFinite);
}

} // namespace prism::test
