#include "benchmark.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

namespace prism {
namespace {

// Nearest-rank percentile of sorted values.
double percentile(const std::vector<double> &sorted, double p) {
    if (sorted.empty())
        return 0.0;
    size_t rank = size_t(std::ceil(p / 100.0 * double(sorted.size())));
    return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

} // namespace

Camera benchmarkCamera(const Camera &start, uint32_t frame, uint32_t frames) {
    double t = frames > 1 ? double(frame) / double(frames - 1) : 0.0;
    double yaw = glm::radians(30.0) * std::sin(2.0 * glm::pi<double>() * t);
    double dolly = 1.0 - 0.2 * std::sin(glm::pi<double>() * t);
    glm::dvec3 up = glm::normalize(glm::dvec3(start.up));
    glm::dvec3 look = start.look;
    glm::dvec3 offset = start.eye - look;
    // Rodrigues rotation of the eye about the up axis through the look point.
    glm::dvec3 rotated = offset * std::cos(yaw) + glm::cross(up, offset) * std::sin(yaw) +
                         up * glm::dot(up, offset) * (1.0 - std::cos(yaw));
    Camera camera = start;
    camera.eye = look + rotated * dolly;
    return camera;
}

std::string benchmarkJson(const BenchmarkReport &r) {
    std::vector<double> sorted = r.frameMs;
    std::sort(sorted.begin(), sorted.end());
    double totalMs = std::accumulate(sorted.begin(), sorted.end(), 0.0);
    nlohmann::json json = {{"tool", "prism-view"},
                           {"scene", r.scene},
                           {"device", r.device},
                           {"width", r.width},
                           {"height", r.height},
                           {"depth", r.depth},
                           {"grid", r.grid},
                           {"present_mode", r.presentMode},
                           {"warmup_frames", r.warmupFrames},
                           {"frames", sorted.size()},
                           {"warmup_ms", r.warmupMs},
                           {"frame_ms_median", percentile(sorted, 50.0)},
                           {"frame_ms_p95", percentile(sorted, 95.0)},
                           {"frame_ms_p99", percentile(sorted, 99.0)},
                           {"fps", totalMs > 0.0 ? 1000.0 * double(sorted.size()) / totalMs : 0.0},
                           {"load_ms", r.loadMs},
                           {"build_ms", r.buildMs},
                           {"grid_cache", {{"state", r.gridCache}}},
                           {"obj_cache", {{"hits", r.objCacheHits}, {"misses", r.objCacheMisses}}},
                           {"rays", r.rays},
                           {"mrays_per_s", totalMs > 0.0 ? double(r.rays) / (totalMs * 1e3) : 0.0}};
    return json.dump();
}

} // namespace prism
