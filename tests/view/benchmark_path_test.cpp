// The --benchmark camera path and its JSON line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "benchmark.h"
#include "fly_camera.h"

namespace prism {
namespace {

TEST(BenchmarkPath, StartsAndEndsAtTheSceneCameraAndMovesEveryFrame) {
    Camera start;
    start.eye = {0.0f, 2.0f, 8.0f};
    start.look = {0.0f, 1.0f, 0.0f};
    uint32_t frames = 50;
    Camera first = benchmarkCamera(start, 0, frames);
    Camera last = benchmarkCamera(start, frames - 1, frames);
    EXPECT_NEAR(glm::length(first.eye - start.eye), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(last.eye - start.eye), 0.0f, 1e-4f);
    for (uint32_t i = 1; i < frames; ++i) {
        Camera a = benchmarkCamera(start, i - 1, frames), b = benchmarkCamera(start, i, frames);
        EXPECT_FALSE(sameCamera(a, b)) << "frame " << i << " would keep accumulating";
        EXPECT_EQ(b.look, start.look);
    }
}

TEST(BenchmarkPath, JsonHasPercentilesAndRate) {
    BenchmarkReport report;
    report.scene = "s.scene";
    for (int i = 1; i <= 100; ++i)
        report.frameMs.push_back(double(i));
    report.rays = 5050000; // over 5050 ms
    nlohmann::json json = nlohmann::json::parse(benchmarkJson(report));
    EXPECT_DOUBLE_EQ(json["frame_ms_median"].get<double>(), 50.0);
    EXPECT_DOUBLE_EQ(json["frame_ms_p95"].get<double>(), 95.0);
    EXPECT_DOUBLE_EQ(json["frame_ms_p99"].get<double>(), 99.0);
    EXPECT_NEAR(json["mrays_per_s"].get<double>(), 1.0, 1e-12);
    EXPECT_EQ(json["frames"].get<int>(), 100);
}

} // namespace
} // namespace prism
