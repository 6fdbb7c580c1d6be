// Tiles left to the background variant (render/traced_tiles.h): no camera ray that could hit
// anything may fall outside the traced rectangle, the rectangle must actually shrink where the
// scene leaves background, and culling must change no pixel, AOV or ray count.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "render/frame_params.h"
#include "render/traced_tiles.h"
#include "render_helpers.h"
#include "scene/scene_origin.h"
#include "scene_builders.h"
#include "test_scenes.h"

namespace prism::test {
namespace {

bool inside(const TileRect &r, uint32_t tx, uint32_t ty) {
    return tx >= r.x0 && tx < r.x1 && ty >= r.y0 && ty < r.y1;
}

// The shader's camera ray (trace.comp, cameraRay) for a sample position, in float as there.
void cameraRay(const gpu::GpuFrameParams &f, glm::vec2 position, glm::dvec3 &origin,
               glm::dvec3 &dir) {
    glm::vec2 uv = position / glm::vec2(f.image.x, f.image.y);
    float x = 2.0f * uv.x - 1.0f, y = 1.0f - 2.0f * uv.y;
    if (gpu::isParallelCamera(f)) {
        origin = glm::vec3(f.eye) + x * glm::vec3(f.du) + y * glm::vec3(f.dv);
        dir = glm::vec3(f.forward);
    } else {
        origin = glm::vec3(f.eye);
        dir = glm::normalize(glm::vec3(f.forward) + x * glm::vec3(f.du) + y * glm::vec3(f.dv));
    }
}

bool hitsBox(glm::dvec3 o, glm::dvec3 d, glm::dvec3 lo, glm::dvec3 hi) {
    double tEnter = 0.0, tExit = INFINITY;
    for (int a = 0; a < 3; ++a) {
        double t0 = (lo[a] - o[a]) / d[a], t1 = (hi[a] - o[a]) / d[a];
        tEnter = std::max(tEnter, std::min(t0, t1));
        tExit = std::min(tExit, std::max(t0, t1));
    }
    return tEnter <= tExit;
}

bool hitsPlane(glm::dvec3 o, glm::dvec3 d, glm::dvec4 plane) {
    double denom = glm::dot(glm::dvec3(plane), d);
    return denom != 0.0 && (plane.w - glm::dot(glm::dvec3(plane), o)) / denom > 0.0;
}

// Every sample position that could see the box or a plane lies in a traced tile; returns the
// share of tiles traced.
double checkConservative(const gpu::GpuFrameParams &frame, const SceneExtent &extent) {
    TileRect rect = tilesThatMayHit(frame, extent);
    const glm::vec2 offsets[] = {
        {0.0f, 0.0f}, {0.5f, 0.5f}, {0.9999f, 0.0f}, {0.0f, 0.9999f}, {0.9999f, 0.9999f}};
    for (uint32_t py = 0; py < frame.image.y; ++py)
        for (uint32_t px = 0; px < frame.image.x; ++px)
            for (glm::vec2 offset : offsets) {
                glm::dvec3 o, d;
                cameraRay(frame, glm::vec2(px, py) + offset, o, d);
                bool mayHit = extent.hasBox && hitsBox(o, d, extent.boxMin, extent.boxMax);
                for (const glm::dvec4 &plane : extent.planes)
                    mayHit = mayHit || hitsPlane(o, d, plane);
                if (mayHit && !inside(rect, px / kTileSize, py / kTileSize)) {
                    ADD_FAILURE() << "pixel " << px << "," << py << " sees the scene outside the "
                                  << "traced tiles [" << rect.x0 << "," << rect.x1 << ")x["
                                  << rect.y0 << "," << rect.y1 << ")";
                    return 1.0;
                }
            }
    TileRect image = imageTiles(frame.image.x, frame.image.y);
    return double(rect.width() * rect.height()) / (image.width() * image.height());
}

gpu::GpuFrameParams frameFor(const Camera &camera, uint32_t width, uint32_t height) {
    return makeFrameParams(camera, width, height, 1, 1);
}

TEST(TracedTiles, NoRayThatMayHitIsLeftToTheBackground) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-6.0, 6.0), size(0.05, 3.0), unit(-1.0, 1.0);
    int shrunk = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Camera camera;
        camera.eye = {coord(rng), coord(rng), coord(rng)};
        camera.look = {coord(rng), coord(rng), coord(rng)};
        if (glm::length(camera.look - camera.eye) < 0.5)
            continue;
        camera.fovDegrees = float(20.0 + 40.0 * (unit(rng) + 1.0));
        if (trial % 3 == 0)
            camera.orthoHeight = float(2.0 + 3.0 * (unit(rng) + 1.0));
        SceneExtent extent;
        extent.hasBox = trial % 5 != 4;
        glm::dvec3 centre{coord(rng), coord(rng), coord(rng)};
        glm::dvec3 half{size(rng), size(rng), size(rng)};
        extent.boxMin = centre - half;
        extent.boxMax = centre + half;
        if (trial % 4 == 1) {
            glm::dvec3 n = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
            extent.planes.push_back(glm::dvec4(n, glm::dot(n, glm::dvec3(0.0, coord(rng), 0.0))));
        }
        // Odd sizes: partial tiles on the right and at the bottom.
        double share = checkConservative(frameFor(camera, 61, 45), extent);
        shrunk += share < 1.0 ? 1 : 0;
    }
    EXPECT_GT(shrunk, 50) << "the traced rectangle should rarely be the whole image here";
}

TEST(TracedTiles, ASmallObjectNeedsOnlyTheTilesAroundIt) {
    Camera camera; // at (0, 0, 5) looking at the origin, 60 degrees
    SceneExtent extent;
    extent.hasBox = true;
    extent.boxMin = glm::dvec3(-0.3);
    extent.boxMax = glm::dvec3(0.3);
    gpu::GpuFrameParams frame = frameFor(camera, 256, 192);
    EXPECT_LT(checkConservative(frame, extent), 0.1);
    TileRect rect = tilesThatMayHit(frame, extent);
    EXPECT_TRUE(inside(rect, 16, 12)); // the centre
}

TEST(TracedTiles, TheSkyAboveAFloorIsLeftToTheBackground) {
    Camera camera;
    camera.eye = {0.0, 1.0, 0.0};
    camera.look = {0.0, 1.0, -1.0}; // level: the horizon runs across the middle
    SceneExtent extent;
    extent.planes.push_back(glm::dvec4(0.0, 1.0, 0.0, 0.0));
    gpu::GpuFrameParams frame = frameFor(camera, 128, 96);
    double share = checkConservative(frame, extent);
    EXPECT_GT(share, 0.4);
    EXPECT_LT(share, 0.6);
    TileRect rect = tilesThatMayHit(frame, extent);
    EXPECT_EQ(rect.y1, 12u); // down to the bottom row
}

TEST(TracedTiles, NothingBehindTheCameraIsTraced) {
    Camera camera;
    SceneExtent extent;
    extent.hasBox = true;
    extent.boxMin = {-1.0, -1.0, 6.0};
    extent.boxMax = {1.0, 1.0, 8.0};
    EXPECT_TRUE(tilesThatMayHit(frameFor(camera, 64, 48), extent).empty());
    camera.orthoHeight = 4.0f;
    EXPECT_TRUE(tilesThatMayHit(frameFor(camera, 64, 48), extent).empty());
}

TEST(TracedTiles, TheRestCoversTheImageOnce) {
    const uint32_t tilesX = 9, tilesY = 7;
    for (TileRect traced : {TileRect{}, TileRect{0, 0, 9, 7}, TileRect{2, 1, 5, 4},
                            TileRect{0, 3, 9, 5}, TileRect{4, 0, 9, 7}}) {
        std::vector<int> covered(tilesX * tilesY, 0);
        std::vector<TileRect> all = tilesAround(traced, imageTiles(tilesX * 8 - 3, tilesY * 8));
        all.push_back(traced);
        for (const TileRect &r : all)
            for (uint32_t y = r.y0; y < r.y1; ++y)
                for (uint32_t x = r.x0; x < r.x1; ++x)
                    covered[y * tilesX + x] += 1;
        for (int c : covered)
            EXPECT_EQ(c, 1);
    }
}

class TracedTilesRender : public GpuTest {};

// Culling is an optimisation only: every pixel, AOV and ray count as without it, for a view
// with background above and beside the scene, an environment, soft shadows and both cameras.
TEST_F(TracedTilesRender, ChangeNoPixel) {
    Scene scene = stabilityScene();
    scene.lights[0].radius = 0.5f;
    scene.camera.eye = {0.0, 3.0, 9.0};
    scene.camera.look = {0.0, 3.5, 0.0}; // the horizon low in the image: sky above
    Texture sky;
    sky.path = "sky";
    sky.width = 4;
    sky.height = 2;
    for (int i = 0; i < 8; ++i)
        sky.texels.push_back(glm::vec4(0.1f * float(i), 0.5f, 0.9f - 0.1f * float(i), 1.0f));
    Scene withSky = scene;
    withSky.textures.push_back(sky);
    withSky.environment.texture = uint32_t(withSky.textures.size() - 1);
    Scene parallel = scene;
    parallel.camera.orthoHeight = 5.0f;
    Scene floating = scene; // no floor: background all round the objects
    floating.planes.clear();
    for (const Scene *s : {&scene, &withSky, &parallel, &floating}) {
        TracerOptions culled, full;
        culled.writeAov = full.writeAov = true;
        full.cullMissTiles = false;
        GpuRender a = renderGpu(context(), *s, 70, 50, 2, 3, GridOptions{}, culled);
        GpuRender b = renderGpu(context(), *s, 70, 50, 2, 3, GridOptions{}, full);
        expectSameFrame(a, b);
    }
    // And the floating scene did leave tiles to the background.
    Scene centred = floating;
    centerOnCamera(centred);
    Grid grid = buildGrid(centred);
    TileRect rect =
        tilesThatMayHit(frameFor(centred.camera, 70, 50), sceneExtent(centred, grid, true));
    EXPECT_LT(rect.width() * rect.height(), 9u * 7u);
}

} // namespace
} // namespace prism::test
