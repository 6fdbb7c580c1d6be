// Scene arrays reach the device in place where it shares the host's memory (lavapipe), through a
// staging buffer elsewhere (render/scene_buffers.h, UploadPath): both give the same arrays, so
// the same frame, and on a CPU device the in-place path is the one taken.
#include <atomic>
#include <cstring>
#include <filesystem>
#include <optional>

#include <gtest/gtest.h>

#include "core/worker_pool.h"
#include "gpu_fixture.h"
#include "render/scene_buffers.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"
#include "test_scenes.h"
#include "vk/commands.h"

namespace prism::test {
namespace {

class SceneUpload : public GpuTest {};

// In place: the device-local buffers are mapped and hold the packed bytes; staged:
// none is mapped.
TEST_F(SceneUpload, InPlaceWhereTheDeviceSharesTheHostsMemory) {
    Scene scene = stabilityScene();
    centerOnCamera(scene);
    Grid grid = buildGrid(scene);
    PackedScene packed = packScene(scene, grid);
    ArrayLimits limits{uint64_t(1) << 30, uint64_t(1) << 27, true};
    vk::CommandRunner runner(context());
    SceneBuffers inPlace = uploadScene(context(), runner, packed, limits);
    SceneBuffers staged = uploadScene(context(), runner, packed, limits, UploadPath::Staged);
    EXPECT_EQ(staged.spheres.buffer.mapped(), nullptr);
    EXPECT_EQ(staged.header.mapped(), nullptr);
    if (!context().sharesHostMemory())
        GTEST_SKIP() << context().deviceName() << " does not share the host's memory";
    ASSERT_NE(inPlace.spheres.buffer.mapped(), nullptr);
    ASSERT_NE(inPlace.header.mapped(), nullptr);
    uint64_t bytes = packed.spheres.size() * sizeof(packed.spheres[0]);
    ASSERT_GT(bytes, 0u);
    EXPECT_EQ(std::memcmp(inPlace.spheres.buffer.mapped(), packed.spheres.data(), bytes), 0);
    EXPECT_EQ(std::memcmp(inPlace.header.mapped(), &packed.header, sizeof(packed.header)), 0);
}

// The same frame either way, for a mesh with textures and spheres on both grids.
TEST_F(SceneUpload, InPlaceAndStagedRenderTheSameFrame) {
    Scene showcase = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "showcase.scene");
    for (const char *grid : {"regular", "adaptive"}) {
        SCOPED_TRACE(grid);
        TracerOptions inPlace, staged;
        inPlace.writeAov = staged.writeAov = true;
        staged.stagedUpload = true;
        GridOptions g = parseGridOption(grid);
        expectSameFrame(renderGpu(context(), showcase, 64, 48, 1, 2, g, inPlace),
                        renderGpu(context(), showcase, 64, 48, 1, 2, g, staged));
    }
}

// The tracer's pipeline compiled beside the arrays' upload (RayTracer::compileBeside, big scenes
// only unless asked) makes the same frame as one after the other.
TEST_F(SceneUpload, CompiledBesideTheUploadRendersTheSameFrame) {
    Scene showcase = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "showcase.scene");
    ASSERT_LT(showcase.finitePrimitiveCount(), TracerOptions{}.compileBesideUploadFrom);
    TracerOptions apart, beside;
    apart.writeAov = beside.writeAov = true;
    beside.compileBesideUploadFrom = 0;
    GridOptions g = parseGridOption("adaptive");
    GpuRender reference = renderGpu(context(), showcase, 64, 48, 1, 2, g, apart);
    expectSameFrame(reference, renderGpu(context(), showcase, 64, 48, 1, 2, g, beside));
    // Made while parallelFor's pool is busy (a tracer made inside a parallel loop): both parts
    // on the calling thread, the same frame.
    std::atomic<int> turn{0};
    std::optional<GpuRender> inBusyPool;
    runOnWorkerPool(1, [&] {
        if (turn++ == 0)
            inBusyPool = renderGpu(context(), showcase, 64, 48, 1, 2, g, beside);
    });
    ASSERT_TRUE(inBusyPool.has_value());
    expectSameFrame(reference, *inBusyPool);
}

} // namespace
} // namespace prism::test
