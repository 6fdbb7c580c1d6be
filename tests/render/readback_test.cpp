// Reading the image back (RayTracer::readback): a frame that copied its image out in its own
// submission (renderFrame's copyOut) reads back what a separate copy reads, AOVs and a region
// included, and never an earlier frame's image.
#include <string>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"

namespace prism::test {
namespace {

class Readback : public GpuTest {};

TEST_F(Readback, AFrameCopiedOutReadsWhatASeparateCopyReads) {
    Scene scene = loadScene(std::string(PRISM_SCENES_DIR) + "/showcase.scene");
    centerOnCamera(scene);
    Grid grid = buildGrid(scene, {});
    TracerOptions options;
    options.maxDepth = 3;
    options.writeAov = true;
    options.region = {5, 3, 41, 30};
    RayTracer tracer(context(), scene, grid, 48, 36, options);
    Camera moved = scene.camera;
    moved.eye += glm::dvec3(0.4, 0.2, 0.0);
    const Camera cameras[] = {scene.camera, moved, scene.camera};
    for (int k = 0; k < 3; ++k) {
        const Camera &camera = cameras[k], &other = cameras[k == 1 ? 0 : 1];
        tracer.renderFrame(camera, 2);
        TracedImage separate = tracer.readback(2);
        tracer.renderFrame(camera, 2, {}, true);
        TracedImage copiedOut = tracer.readback(2);
        EXPECT_EQ(copiedOut.rgba, separate.rgba);
        EXPECT_EQ(copiedOut.depth, separate.depth);
        EXPECT_EQ(copiedOut.normal, separate.normal);
        // The next frame, another camera, without copyOut: its readback is its own image.
        tracer.renderFrame(other, 2, {}, true);
        tracer.renderFrame(camera, 2);
        EXPECT_EQ(tracer.readback(2).rgba, separate.rgba);
    }
}

} // namespace
} // namespace prism::test
