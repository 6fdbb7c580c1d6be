// Resumable tracing (shaders/resume.glsl): a sample traced over many dispatches, interrupted
// wherever its lane budget runs out, is the sample traced in one: the same bits in colour,
// depth and normal, and the same ray counts.
#include <string>

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

// Every shipped scene traced resumably: the same image as one dispatch, and its walks were
// interrupted (more dispatches than tiles; a budget that never ran out would compare nothing).
// No one budget does both for every scene: a small scene's samples fit in a few hundred steps,
// while the budget must hold a whole replay of a sample's walks, or the tracer refuses the frame
// (BudgetTooSmallForTheReplayIsRefused). So each scene starts at a quarter of the default and
// steps down by a quarter until its walks are interrupted. Measured: at a quarter, the old fixed
// budget, 9 of the 14 scenes were never interrupted; stepping down, each is by 353-1,975 (the
// bunny last), where the smallest budgets their replays fit in are 64-518.
TEST_F(Resumable, ShippedScenesMatchOneDispatch) {
    for (const std::string &name : shippedScenes()) {
        SCOPED_TRACE(name);
        Scene scene = loadScene(std::string(PRISM_SCENES_DIR) + "/" + name + ".scene");
        TracerOptions options;
        options.resumable = true;
        ResumePlan plan = planResume(48, 36, 5, 1, false, options.resumeMemoryBytes);
        uint32_t tiles = ((48 + plan.tileWidth - 1) / plan.tileWidth) *
                         ((36 + plan.tileHeight - 1) / plan.tileHeight);
        GpuRender resumed;
        for (uint32_t budget = gpu::kResumeLaneBudget / 4;; budget -= budget / 4) {
            SCOPED_TRACE("budget " + std::to_string(budget));
            options.resumeLaneBudget = budget;
            resumed = renderGpu(context(), scene, 48, 36, 1, 5, {}, options); // refused: fails
            if (resumed.frame.resumeDispatches > tiles || budget < 64)
                break;
        }
        EXPECT_GT(resumed.frame.resumeDispatches, tiles)
            << "walks never interrupted, down to budget " << options.resumeLaneBudget;
        expectSameFrame(resumed, renderGpu(context(), scene, 48, 36, 1, 5));
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
