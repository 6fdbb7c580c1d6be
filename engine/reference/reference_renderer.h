#pragma once
// The CPU reference renderer: every pixel sample traced in double precision against every
// primitive (no grid), on all cores. Ground truth for the shader's images, ray counts and AOVs.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/ray_counts.h"
#include "reference/camera_model.h"
#include "scene/scene.h"

namespace prism {

struct RenderSettings {
    int width = 1024;
    int height = 768;
    uint32_t samplesPerPixel = 1;
    uint32_t maxDepth = 5; // 1 = primary and shadow rays only
    std::optional<Camera> camera; // an animated scene's frame (camera_animation.h); else its own
    uint32_t seed = 0;            // the sampling seed (shared/sampling.h: samplingKey)
};

struct RenderedImage {
    int width = 0, height = 0;
    std::vector<glm::vec4> rgba;   // linear radiance, mean over the samples, alpha 1
    std::vector<float> depth;      // distance along the pixel-centre ray; +infinity on a miss
    std::vector<glm::vec3> normal; // unit geometric normal facing that ray; 0 on a miss
    RayCounts rays;
};

// Renders `scene` through its camera, in double precision relative to the camera's eye (so
// the picture does not depend on where the scene sits). Pixel index = y * width + x, row 0
// at the top.
// `progress`, when given, is called from the calling thread with the fraction of rows done.
// Throws prism::Error for bad settings or a scene that names missing materials or textures.
RenderedImage renderReference(const Scene &scene, const RenderSettings &settings,
                              const std::function<void(double)> &progress = {});

// Radiance of one sample of pixel (px, py): the primary ray through pixelSamplePosition,
// traced up to maxDepth, its sample numbers drawn under `seed`. Adds the rays it traces
// (1 primary, shadow, secondary) to `rays`.
glm::dvec3 tracePixelSample(const Scene &scene, const CameraFrame &frame, int px, int py,
                            uint32_t sampleIndex, uint32_t spp, uint32_t maxDepth, RayCounts &rays,
                            uint32_t seed = 0);

} // namespace prism
