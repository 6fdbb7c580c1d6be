#pragma once
// Values between keys (format 1.2, docs/scene-format.md, "Animation"), shared by the camera's
// keys and the placements': the segment of the key list that holds a frame, and one value
// blended through it, linearly or by a Catmull-Rom spline. A key type has a `frame` field.
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

#include "scene/scene.h"

namespace prism {

// Where a frame falls among keys in increasing frame order: between keys[i] and keys[i + 1], a
// fraction u of the way (0 <= u < 1). Only for frames strictly inside the keys' span.
struct KeySegment {
    size_t i = 0;
    double u = 0.0;
};

template <typename Key>
KeySegment keySegment(const std::vector<Key> &keys, double frame) {
    auto after = std::upper_bound(keys.begin(), keys.end(), frame,
                                  [](double f, const Key &k) { return f < k.frame; });
    size_t i = size_t(std::distance(keys.begin(), after)) - 1;
    return {i, (frame - keys[i].frame) / (keys[i + 1].frame - keys[i].frame)};
}

// Cubic Hermite basis on [0, 1] (the four weights of p0, m0, p1, m1).
struct Hermite {
    double h00, h10, h01, h11;
    explicit Hermite(double u) {
        double u2 = u * u, u3 = u2 * u;
        h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
        h10 = u3 - 2.0 * u2 + u;
        h01 = -2.0 * u3 + 3.0 * u2;
        h11 = u3 - u2;
    }
};

// One value through the keys at `segment`: `get` picks it from a key. Linear between keys i and
// i + 1, or Catmull-Rom with non-uniform tangents (the slope over the neighbouring keys' frames,
// one-sided at the ends), so that keys far apart in time do not overshoot.
template <typename Value, typename Key, typename Get>
Value blendKeys(const std::vector<Key> &keys, KeySegment segment, KeyInterpolation mode, Get get) {
    size_t i = segment.i;
    const Value a = get(keys[i]), b = get(keys[i + 1]);
    if (mode == KeyInterpolation::Linear)
        return a + (b - a) * segment.u;
    auto slope = [&](size_t k) {
        size_t before = k == 0 ? 0 : k - 1, after = std::min(k + 1, keys.size() - 1);
        return (get(keys[after]) - get(keys[before])) / (keys[after].frame - keys[before].frame);
    };
    double span = keys[i + 1].frame - keys[i].frame;
    Hermite h(segment.u);
    return a * h.h00 + slope(i) * (h.h10 * span) + b * h.h01 + slope(i + 1) * (h.h11 * span);
}

} // namespace prism
