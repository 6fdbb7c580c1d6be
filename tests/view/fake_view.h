#pragma once
// A viewer without a window for the driver's tests: records what the driver asks of it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "view_driver.h"

namespace prism::test {

class FakeView : public ViewControls {
public:
    void requestWindowSize(uint32_t width, uint32_t height) override {
        resizes.push_back(std::to_string(width) + "x" + std::to_string(height));
    }
    bool reloadSceneFrom(const std::filesystem::path &path) override {
        reloads.push_back(path);
        return reloadSucceeds;
    }
    const std::filesystem::path &scenePath() const override { return path; }
    const Camera &sceneCamera() const override { return scene; }
    glm::dvec3 sceneOrigin() const override { return origin; }
    void placeCamera(const Camera &camera) override { placed.push_back(camera); }
    bool setFeatures(const FeatureToggles &wanted) override {
        featureChanges.push_back(wanted);
        if (!featuresSucceed)
            return false;
        current = wanted;
        return true;
    }
    const FeatureToggles &features() const override { return current; }
    void saveScreenshot(const std::filesystem::path &base) override { screenshots.push_back(base); }
    bool converged() const override { return isConverged; }
    uint32_t samplesTarget() const override { return 4; }
    uint32_t validationMessages() const override { return messages; }

    std::filesystem::path path = "s.scene";
    Camera scene;
    glm::dvec3 origin{0.0};
    FeatureToggles current;
    bool isConverged = false, reloadSucceeds = true, featuresSucceed = true;
    uint32_t messages = 0;
    std::vector<std::string> resizes;
    std::vector<std::filesystem::path> reloads, screenshots;
    std::vector<Camera> placed;
    std::vector<FeatureToggles> featureChanges;
};

} // namespace prism::test
