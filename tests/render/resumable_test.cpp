// Resumable tracing (shaders/resume.glsl): a sample traced over many dispatches, interrupted
// wherever its lane budget runs out, is the sample traced in one: the same bits in colour,
// depth and normal, and the same ray counts.
#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu_fixture.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "shared/trace_interface.h"
#include "shipped_scenes.h"
#include "test_scenes.h"

namespace prism::test {
namespace {

class Resumable : public GpuTest {};

// Small budgets interrupt walks in mid-cell, between walks, in shadow walks and in reflected
// and refracted rays: a cloud of 300 spheres makes walks long (on the regular grid one cell
// holds everything: 2,000 iterations a dispatch; the adaptive grid's walks are short: 300, at
// depth 2 so that a replay fits). A 20 KiB memory budget splits the 40x30 image into tiles.
// Two samples (the records start again for each), AOVs on.
TEST_F(Resumable, InterruptedEverywhereMatchesOneDispatch) {
    Scene scene = stabilityScene();
    scene.lights.push_back(Light{{-3.0f, 4.0f, 2.0f}, {0.5f, 0.5f, 0.6f}, 0.3f}); // area light
    for (int k = 0; k < 300; ++k) // a cloud of small spheres
        scene.spheres.push_back(
            Sphere{{-3.0f + 0.02f * k, 0.2f + 0.05f * (k % 7), 2.0f - 0.1f * (k % 11)}, 0.04f, 4});
    struct Case {
        const char *grid;
        uint32_t budget, depth;
    };
    for (Case c : {Case{"1", 2000, 5}, Case{"adaptive", 300, 2}}) {
        SCOPED_TRACE(c.grid);
        TracerOptions plainOptions;
        plainOptions.writeAov = true;
        TracerOptions resumeOptions = plainOptions;
        resumeOptions.resumable = true;
        resumeOptions.resumeLaneBudget = c.budget;
        resumeOptions.resumeMemoryBytes = 20 << 10;
        GridOptions grid = parseGridOption(c.grid);
        GpuRender plain = renderGpu(context(), scene, 40, 30, 2, c.depth, grid, plainOptions);
        GpuRender resumed = renderGpu(context(), scene, 40, 30, 2, c.depth, grid, resumeOptions);
        expectSameFrame(resumed, plain);
        EXPECT_EQ(plain.frame.resumeDispatches, 0u);
        // More dispatches than tiles x samples: samples were interrupted and resumed.
        ResumePlan plan = planResume(40, 30, c.depth, 2, true, 20 << 10);
        uint32_t tiles = ((40 + plan.tileWidth - 1) / plan.tileWidth) *
                         ((30 + plan.tileHeight - 1) / plan.tileHeight);
        EXPECT_GT(tiles, 1u);
        EXPECT_GT(resumed.frame.resumeDispatches, 2 * tiles);
    }
}

// Every shipped scene, with a quarter of the default budget: the same image as one dispatch.
TEST_F(Resumable, ShippedScenesMatchOneDispatch) {
    for (const std::string &name : shippedScenes()) {
        SCOPED_TRACE(name);
        Scene scene = loadScene(std::string(PRISM_SCENES_DIR) + "/" + name + ".scene");
        TracerOptions options;
        options.resumable = true;
        options.resumeLaneBudget = gpu::kResumeLaneBudget / 4;
        expectSameFrame(renderGpu(context(), scene, 48, 36, 1, 5, {}, options),
                        renderGpu(context(), scene, 48, 36, 1, 5));
    }
}

// A sample whose walks cannot be replayed within the budget is refused by name, not looped on.
TEST_F(Resumable, BudgetTooSmallForTheReplayIsRefused) {
    TracerOptions options;
    options.resumable = true;
    options.resumeLaneBudget = 20;
    try {
        renderGpu(context(), stabilityScene(), 16, 12, 1, 5, {}, options);
        FAIL() << "expected an error";
    } catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("cannot be finished"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace prism::test
