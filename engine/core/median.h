#pragma once
// The median of a set of timings: what every benchmark in Prism reports (0 for none).
#include <algorithm>
#include <vector>

namespace prism {

inline double median(std::vector<double> values) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace prism
