// Tiles left to the background variant (render/traced_tiles.h): no camera ray that could hit
// anything may fall outside the traced rectangle, the rectangle must actually shrink where the
// scene leaves background, and culling must change no pixel, AOV or ray count.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/parallel_for.h"
#include "gpu_fixture.h"
#include "render/frame_params.h"
#include "render/lavapipe_threads.h"
#include "render/plane_shadows.h"
#include "render/traced_tiles.h"
#include "render_helpers.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"
#include "scene_builders.h"
#include "test_scenes.h"
#include "vk/commands.h"

namespace prism::test {
namespace {

bool traced(const std::vector<uint8_t> &mayHit, const gpu::GpuFrameParams &f, uint32_t tx,
            uint32_t ty) {
    return mayHit[size_t(ty) * imageTiles(f.image.x, f.image.y).x1 + tx] != 0;
}

double tracedShare(const std::vector<uint8_t> &mayHit) {
    return double(std::count(mayHit.begin(), mayHit.end(), uint8_t(1))) / double(mayHit.size());
}

Aabb boxOf(glm::dvec3 lo, glm::dvec3 hi) {
    Aabb b;
    b.min = lo;
    b.max = hi;
    return b;
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

// Calls visit(px, py, o, d) for the shader's camera ray at five sample positions of every pixel
// (its corners and centre) until visit returns false; returns whether none did.
template <typename Visit> bool forEachSampleRay(const gpu::GpuFrameParams &frame, Visit visit) {
    const glm::vec2 offsets[] = {
        {0.0f, 0.0f}, {0.5f, 0.5f}, {0.9999f, 0.0f}, {0.0f, 0.9999f}, {0.9999f, 0.9999f}};
    for (uint32_t py = 0; py < frame.image.y; ++py)
        for (uint32_t px = 0; px < frame.image.x; ++px)
            for (glm::vec2 offset : offsets) {
                glm::dvec3 o, d;
                cameraRay(frame, glm::vec2(px, py) + offset, o, d);
                if (!visit(px, py, o, d))
                    return false;
            }
    return true;
}

// Every sample position that could see a box or a plane lies in a traced tile; returns the
// share of tiles traced. Both ways the tiles that see the boxes are found: by projecting the
// boxes, and from the start distances of the same boxes taken as start blocks (the tracer's
// way, where it has the starts).
double checkConservative(const gpu::GpuFrameParams &frame, const SceneExtent &extent) {
    std::vector<float> starts = tileStartDistances(frame, extent.boxes);
    std::vector<uint8_t> mayHit = tilesThatMayHit(frame, extent);
    std::vector<uint8_t> mayHitByStarts = tilesThatMayHit(frame, extent, &starts);
    bool ok = forEachSampleRay(frame, [&](uint32_t px, uint32_t py, glm::dvec3 o, glm::dvec3 d) {
        bool mayHitHere = false;
        for (const Aabb &box : extent.boxes)
            mayHitHere = mayHitHere || hitsBox(o, d, box.min, box.max);
        for (const glm::dvec4 &plane : extent.planes)
            mayHitHere = mayHitHere || hitsPlane(o, d, plane);
        for (const std::vector<uint8_t> *flags : {&mayHit, &mayHitByStarts})
            if (mayHitHere && !traced(*flags, frame, px / kTileSize, py / kTileSize)) {
                ADD_FAILURE() << "pixel " << px << "," << py
                              << " sees the scene in a tile left to the background"
                              << (flags == &mayHit ? "" : " (tiles from the start distances)");
                return false;
            }
        return true;
    });
    return ok ? tracedShare(mayHit) : 1.0;
}

gpu::GpuFrameParams frameFor(const Camera &camera, uint32_t width, uint32_t height) {
    return makeFrameParams(camera, width, height, 1, 1);
}

// A random view for the trials below: eye and target in [-6, 6]^3, 20-100 degrees, every
// third trial a parallel camera; none where the eye and the target nearly meet.
std::optional<Camera> randomCamera(std::mt19937 &rng, int trial) {
    std::uniform_real_distribution<double> coord(-6.0, 6.0), unit(-1.0, 1.0);
    Camera camera;
    camera.eye = {coord(rng), coord(rng), coord(rng)};
    camera.look = {coord(rng), coord(rng), coord(rng)};
    if (glm::length(camera.look - camera.eye) < 0.5)
        return std::nullopt;
    camera.fovDegrees = float(20.0 + 40.0 * (unit(rng) + 1.0));
    if (trial % 3 == 0)
        camera.orthoHeight = float(2.0 + 3.0 * (unit(rng) + 1.0));
    return camera;
}

// A random box in [-6, 6]^3, 0.1 to 6 a side.
Aabb randomBox(std::mt19937 &rng) {
    std::uniform_real_distribution<double> coord(-6.0, 6.0), size(0.05, 3.0);
    glm::dvec3 centre{coord(rng), coord(rng), coord(rng)};
    glm::dvec3 half{size(rng), size(rng), size(rng)};
    return boxOf(centre - half, centre + half);
}

TEST(TracedTiles, NoRayThatMayHitIsLeftToTheBackground) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-6.0, 6.0), unit(-1.0, 1.0);
    int shrunk = 0;
    for (int trial = 0; trial < 200; ++trial) {
        std::optional<Camera> camera = randomCamera(rng, trial);
        if (!camera)
            continue;
        SceneExtent extent;
        for (int box = 0; box < (trial % 5 == 4 ? 0 : 1 + trial % 3); ++box)
            extent.boxes.push_back(randomBox(rng));
        if (trial % 4 == 1) {
            glm::dvec3 n = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
            extent.planes.push_back(glm::dvec4(n, glm::dot(n, glm::dvec3(0.0, coord(rng), 0.0))));
        }
        // Odd sizes: partial tiles on the right and at the bottom.
        double share = checkConservative(frameFor(*camera, 61, 45), extent);
        shrunk += share < 1.0 ? 1 : 0;
    }
    EXPECT_GT(shrunk, 50) << "the traced tiles should rarely be the whole image here";
}

TEST(TracedTiles, ASmallObjectNeedsOnlyTheTilesAroundIt) {
    Camera camera; // at (0, 0, 5) looking at the origin, 60 degrees
    SceneExtent extent;
    extent.boxes.push_back(boxOf(glm::dvec3(-0.3), glm::dvec3(0.3)));
    gpu::GpuFrameParams frame = frameFor(camera, 256, 192);
    EXPECT_LT(checkConservative(frame, extent), 0.1);
    EXPECT_TRUE(traced(tilesThatMayHit(frame, extent), frame, 16, 12)); // the centre
}

// Two boxes far apart on the screen: the tiles between them are not traced (a rectangle round
// both would have traced them).
TEST(TracedTiles, TheGapBetweenTwoObjectsIsLeftToTheBackground) {
    Camera camera;
    SceneExtent extent;
    extent.boxes.push_back(boxOf({-2.0, -0.2, -0.2}, {-1.6, 0.2, 0.2}));
    extent.boxes.push_back(boxOf({1.6, -0.2, -0.2}, {2.0, 0.2, 0.2}));
    gpu::GpuFrameParams frame = frameFor(camera, 256, 192);
    std::vector<uint8_t> mayHit = tilesThatMayHit(frame, extent);
    EXPECT_LT(checkConservative(frame, extent), 0.1);
    EXPECT_FALSE(traced(mayHit, frame, 16, 12)); // the centre, between them
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
    std::vector<uint8_t> mayHit = tilesThatMayHit(frame, extent);
    for (uint32_t tx = 0; tx < 16; ++tx) {
        EXPECT_TRUE(traced(mayHit, frame, tx, 11)) << "the bottom row";
        EXPECT_FALSE(traced(mayHit, frame, tx, 0)) << "the top row";
    }
}

TEST(TracedTiles, NothingBehindTheCameraIsTraced) {
    Camera camera;
    SceneExtent extent;
    extent.boxes.push_back(boxOf({-1.0, -1.0, 6.0}, {1.0, 1.0, 8.0}));
    EXPECT_EQ(tracedShare(tilesThatMayHit(frameFor(camera, 64, 48), extent)), 0.0);
    camera.orthoHeight = 4.0f;
    EXPECT_EQ(tracedShare(tilesThatMayHit(frameFor(camera, 64, 48), extent)), 0.0);
}

// A box round the eye's plane may be seen anywhere.
TEST(TracedTiles, ABoxRoundTheEyeTracesEverything) {
    Camera camera;
    SceneExtent extent;
    extent.boxes.push_back(boxOf({2.0, -1.0, 4.0}, {3.0, 1.0, 6.0}));
    EXPECT_EQ(tracedShare(tilesThatMayHit(frameFor(camera, 64, 48), extent)), 1.0);
}

// Where a camera ray (o + t d, t >= 0) enters a box, or infinity where it misses it.
double boxEntry(glm::dvec3 o, glm::dvec3 d, const Aabb &box) {
    double tEnter = 0.0, tExit = INFINITY;
    for (int a = 0; a < 3; ++a) {
        double t0 = (box.min[a] - o[a]) / d[a], t1 = (box.max[a] - o[a]) / d[a];
        tEnter = std::max(tEnter, std::min(t0, t1));
        tExit = std::min(tExit, std::max(t0, t1));
    }
    return tEnter <= tExit ? tEnter : INFINITY;
}

// A tile's start distance is a lower bound: no camera ray of the tile (the shader's float ray,
// at its corners and centre and beyond) enters a box before it, for both cameras, boxes round
// the eye and behind it. And it is not a trivial one: most tiles whose rays meet a box in front
// start past the eye.
TEST(TracedTiles, NoCameraRayMeetsABoxBeforeItsTileStarts) {
    std::mt19937 rng(17);
    size_t seeing = 0, started = 0;
    for (int trial = 0; trial < 200; ++trial) {
        std::optional<Camera> camera = randomCamera(rng, trial);
        if (!camera)
            continue;
        std::vector<Aabb> boxes;
        for (int box = 0; box < 1 + trial % 4; ++box)
            boxes.push_back(randomBox(rng));
        gpu::GpuFrameParams frame = frameFor(*camera, 61, 45);
        std::vector<float> starts = tileStartDistances(frame, boxes);
        uint32_t tilesX = imageTiles(frame.image.x, frame.image.y).x1;
        ASSERT_EQ(starts.size(), size_t(tilesX) * imageTiles(61, 45).y1);
        std::vector<double> nearest(starts.size(), INFINITY);
        forEachSampleRay(frame, [&](uint32_t px, uint32_t py, glm::dvec3 o, glm::dvec3 d) {
            size_t tile = size_t(py / kTileSize) * tilesX + px / kTileSize;
            for (const Aabb &box : boxes)
                nearest[tile] = std::min(nearest[tile], boxEntry(o, d, box));
            return true;
        });
        for (size_t tile = 0; tile < starts.size(); ++tile) {
            ASSERT_LE(double(starts[tile]), nearest[tile])
                << "trial " << trial << ", tile " << tile << ": a ray meets a box before";
            if (std::isfinite(nearest[tile]) && nearest[tile] > 0.0) {
                ++seeing;
                started += starts[tile] > 0.0f ? 1 : 0;
            }
        }
    }
    EXPECT_GT(double(started), 0.5 * double(seeing));
}

// One box ahead: the tile through its middle starts within a thousandth of the box's distance.
TEST(TracedTiles, ATileStartsAtTheNearestBoxItSees) {
    Camera camera; // at (0, 0, 5) looking at the origin
    std::vector<Aabb> boxes{boxOf(glm::dvec3(-0.5), glm::dvec3(0.5))};
    gpu::GpuFrameParams frame = frameFor(camera, 64, 48);
    std::vector<float> starts = tileStartDistances(frame, boxes);
    float middle = starts[size_t(3) * 8 + 4];
    EXPECT_LE(middle, 4.5f);
    EXPECT_GT(middle, 4.5f * 0.999f);
    EXPECT_EQ(starts[0], kNoBoxAhead) << "a corner tile sees no box";
    camera.orthoHeight = 3.0f; // parallel rays from the image plane through the eye
    frame = frameFor(camera, 64, 48);
    starts = tileStartDistances(frame, boxes);
    EXPECT_LE(starts[size_t(3) * 8 + 4], 4.5f);
    EXPECT_GT(starts[size_t(3) * 8 + 4], 4.5f * 0.999f);
}

// Many boxes are split over threads, each part its own distances: every tile still gets the
// least of all the boxes' own starts, at any thread count.
TEST(TracedTiles, ManyBoxesStartWhereEachAloneWould) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(-3.0, 3.0);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 13000; ++i) { // three parts of at least 4,096 boxes
        glm::dvec3 lo(unit(rng), unit(rng), unit(rng) - 2.0);
        boxes.push_back(boxOf(lo, lo + glm::dvec3(0.05)));
    }
    Camera camera; // at (0, 0, 5) looking at the origin
    gpu::GpuFrameParams frame = frameFor(camera, 64, 48);
    std::vector<float> expected(48, kNoBoxAhead);
    for (const Aabb &box : boxes) {
        std::vector<float> alone = tileStartDistances(frame, {box});
        for (size_t tile = 0; tile < expected.size(); ++tile)
            expected[tile] = std::min(expected[tile], alone[tile]);
    }
    for (unsigned threads : {1u, 2u, 3u}) {
        ParallelThreads limit(threads);
        EXPECT_EQ(tileStartDistances(frame, boxes), expected) << threads << " threads";
    }
    EXPECT_LT(*std::max_element(expected.begin(), expected.end()), kNoBoxAhead)
        << "every tile sees a box";
}

// A big scene's blocks are marked by each thread's share of the primitives and merged: the
// same boxes, in the same order, at every thread count (60,000 small triangles in a shell).
TEST(TracedTiles, TheExtentsBlocksAreTheSameAtEveryThreadCount) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Scene scene = stabilityScene();
    for (int i = 0; i < 60'000; ++i) {
        glm::dvec3 c = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng))) * 3.0;
        glm::vec3 p(c);
        addTriangle(scene, p, p + glm::vec3(0.02f, 0.0f, 0.0f), p + glm::vec3(0.0f, 0.02f, 0.0f),
                    0);
    }
    Grid grid = buildGrid(scene);
    SceneExtent one;
    {
        ParallelThreads limit(1);
        one = sceneExtent(scene, grid);
    }
    ASSERT_GT(one.boxes.size(), 100u) << "a shell of blocks";
    for (unsigned threads : {2u, 3u}) {
        ParallelThreads limit(threads);
        SceneExtent again = sceneExtent(scene, grid);
        EXPECT_TRUE(sameBoxes(again.boxes, one.boxes)) << threads << " threads";
        EXPECT_TRUE(sameBoxes(again.startBoxes, one.startBoxes)) << threads << " threads";
    }
}

// The blocks hold every primitive's surface: points on every triangle and sphere lie in one of
// them. `primitives` more small spheres (a packed mass of them where there are many) are added
// to the stability scene; the boxes stay within their caps.
void expectExtentHoldsEverySurface(int primitives) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene scene = stabilityScene();
    addTriangle(scene, {-6.0f, 0.1f, -5.0f}, {6.0f, 0.3f, -4.0f}, {0.0f, 5.0f, -6.0f}, 0);
    for (int i = 0; i < primitives; ++i) {
        Sphere s = scene.spheres.front();
        s.center = glm::dvec3(4.0 * unit(rng) - 2.0, 1.0 + 2.0 * unit(rng), 4.0 * unit(rng) - 2.0);
        s.radius = float(0.1 + 0.3 * unit(rng));
        scene.spheres.push_back(s);
    }
    Grid grid = buildGrid(scene);
    SceneExtent extent = sceneExtent(scene, grid);
    ASSERT_EQ(extent.planes.size(), 1u);
    uint32_t blocks = kExtentBlocks * kExtentBlocks * kExtentBlocks;
    EXPECT_LT(extent.boxes.size(), blocks / 4) << "mostly empty space here";
    EXPECT_LE(extent.boxes.size(), kMaxExtentBoxes);
    EXPECT_LE(extent.startBoxes.size(), kMaxStartBoxes);
    if (primitives == 0) {
        EXPECT_GT(extent.startBoxes.size(), extent.boxes.size()) << "the start blocks are finer";
    }
    auto heldBy = [&](const std::vector<Aabb> &boxes, glm::dvec3 p) {
        for (const Aabb &b : boxes)
            if (glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max)))
                return true;
        return false;
    };
    auto held = [&](glm::dvec3 p) {
        return heldBy(extent.boxes, p) && heldBy(extent.startBoxes, p);
    };
    for (const Triangle &t : scene.triangles)
        for (int k = 0; k < 200; ++k) {
            double u = unit(rng), v = unit(rng) * (1.0 - u);
            glm::dvec3 p = t.p[0] + u * (t.p[1] - t.p[0]) + v * (t.p[2] - t.p[0]);
            EXPECT_TRUE(held(p)) << p.x << "," << p.y << "," << p.z;
        }
    // In a packed mass, the first few hundred spheres (alike: the boxes are searched one by one).
    size_t spheres = std::min<size_t>(scene.spheres.size(), 300);
    for (size_t i = 0; i < spheres; ++i)
        for (int k = 0; k < (primitives > 0 ? 20 : 200); ++k) {
            const Sphere &s = scene.spheres[i];
            double z = 2.0 * unit(rng) - 1.0, phi = 6.283185307 * unit(rng);
            double r = std::sqrt(1.0 - z * z);
            glm::dvec3 p =
                s.center + double(s.radius) * glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
            EXPECT_TRUE(held(p)) << p.x << "," << p.y << "," << p.z;
        }
}

TEST(TracedTiles, TheExtentsBlocksHoldEveryPrimitive) {
    expectExtentHoldsEverySurface(0);
}

// Tiny triangles scattered through a volume fill eight times the blocks a level, not four as
// a surface does: a level past the cap is made and dropped, never kept.
TEST(TracedTiles, ScatteredTrianglesKeepTheBlocksWithinTheirCaps) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> unit(-5.0f, 5.0f);
    Scene scene = stabilityScene();
    for (int i = 0; i < 40000; ++i) {
        glm::vec3 p(unit(rng), unit(rng) + 6.0f, unit(rng));
        addTriangle(scene, p, p + glm::vec3(0.01f, 0.0f, 0.0f), p + glm::vec3(0.0f, 0.01f, 0.0f),
                    0);
    }
    SceneExtent extent = sceneExtent(scene, buildGrid(scene));
    EXPECT_LE(extent.boxes.size(), kMaxExtentBoxes);
    EXPECT_LE(extent.startBoxes.size(), kMaxStartBoxes);
    EXPECT_GT(extent.startBoxes.size(), kMaxStartBoxes / 8) << "not coarser than it needs";
}

// A packed mass of spheres: blocks coarser than the finest, where the spheres' surfaces would
// fill too many.
TEST(TracedTiles, TheExtentsBlocksHoldEverySurfaceOfAPackedMass) {
    expectExtentHoldsEverySurface(int(kMaxStartBoxes) + 100);
}

// lavapipe gives each thread one contiguous share of a dispatch: every share of the row order
// must hold rows from all over the image, for two threads and for three when their number is
// not known (bit-reversed order), and for the number given when it is, each share's rows then
// in order, down the image.
TEST(TracedTiles, EveryShareOfTheRowOrderSpansTheImage) {
    for (uint32_t known : {0u, 1u, 2u, 3u})
        for (uint32_t rows : {1u, 2u, 7u, 96u, 100u, 256u}) {
            std::vector<uint32_t> order = spreadRowOrder(rows, known);
            std::vector<uint32_t> sorted = order;
            std::sort(sorted.begin(), sorted.end());
            ASSERT_EQ(sorted.size(), rows);
            for (uint32_t r = 0; r < rows; ++r)
                ASSERT_EQ(sorted[r], r) << "a permutation of " << rows << " rows";
            if (known > 0) { // `known` runs down the image, one after the other
                uint32_t descents = 0;
                for (uint32_t i = 1; i < rows; ++i)
                    descents += order[i - 1] > order[i] ? 1u : 0u;
                EXPECT_LE(descents + 1, std::max(1u, std::min(known, rows))) << rows << " rows";
            }
            if (rows < 96)
                continue;
            for (uint32_t shares :
                 known > 0 ? std::vector<uint32_t>{known} : std::vector<uint32_t>{2u, 3u})
                for (uint32_t share = 0; share < shares; ++share) {
                    // Rows of this share in each eighth of the image: about 1/shares of each.
                    std::vector<uint32_t> perEighth(8, 0);
                    uint32_t first = rows * share / shares, last = rows * (share + 1) / shares;
                    for (uint32_t i = first; i < last; ++i)
                        perEighth[order[i] * 8 / rows] += 1;
                    for (uint32_t count : perEighth) {
                        EXPECT_GE(count * shares * 8, rows * 2 / 3)
                            << rows << " rows, share " << share << ", known " << known;
                        EXPECT_LE(count * shares * 8, rows * 3 / 2)
                            << rows << " rows, share " << share << ", known " << known;
                    }
                }
        }
}

// lavapipe's threads as Mesa counts them: one per CPU from two CPUs up, LP_NUM_THREADS when it
// is a whole number, at most 16; a dispatch on no thread pool is one share.
TEST(TracedTiles, LavapipeSharesADispatchAsMesaDoes) {
    EXPECT_EQ(lavapipeDispatchShares(2, nullptr), 2u);
    EXPECT_EQ(lavapipeDispatchShares(1, nullptr), 1u);
    EXPECT_EQ(lavapipeDispatchShares(0, nullptr), 1u);
    EXPECT_EQ(lavapipeDispatchShares(8, "3"), 3u);
    EXPECT_EQ(lavapipeDispatchShares(8, "0"), 1u);
    EXPECT_EQ(lavapipeDispatchShares(8, "three"), 8u);
    EXPECT_EQ(lavapipeDispatchShares(8, ""), 8u);
    EXPECT_EQ(lavapipeDispatchShares(64, nullptr), 16u);
}

TEST(TracedTiles, TheListsCoverTheImageOnceByClass) {
    TileRect image = imageTiles(9 * 8 - 3, 7 * 8);
    std::mt19937 rng(3);
    std::vector<uint8_t> classes(9 * 7);
    for (uint8_t &c : classes)
        c = uint8_t(rng() % 3);
    TileLists lists = tileLists(classes, image);
    ASSERT_EQ(lists.tiles.size(), classes.size());
    EXPECT_GT(lists.full, 0u);
    EXPECT_GT(lists.traced, lists.full);
    EXPECT_LT(lists.traced, classes.size());
    std::vector<int> covered(classes.size(), 0);
    for (size_t i = 0; i < lists.tiles.size(); ++i) {
        uint32_t x = lists.tiles[i] & 0xFFFFu, y = lists.tiles[i] >> 16u;
        ASSERT_LT(x, 9u);
        ASSERT_LT(y, 7u);
        covered[y * 9 + x] += 1;
        uint8_t expected = i < lists.full     ? kTileFull
                           : i < lists.traced ? kTilePlanesOnly
                                              : kTileBackground;
        EXPECT_EQ(classes[y * 9 + x], expected);
    }
    for (int c : covered)
        EXPECT_EQ(c, 1);
}

// The tile that sees world point p (perspective frames).
uint8_t classAt(const std::vector<uint8_t> &classes, const gpu::GpuFrameParams &f, glm::dvec3 p) {
    glm::dvec3 abc =
        glm::inverse(glm::dmat3(glm::dvec3(f.du), glm::dvec3(f.dv), glm::dvec3(f.forward))) *
        (p - glm::dvec3(f.eye));
    double px = (abc.x / abc.z + 1.0) * 0.5 * f.image.x,
           py = (1.0 - abc.y / abc.z) * 0.5 * f.image.y;
    EXPECT_TRUE(abc.z > 0.0 && px >= 0.0 && py >= 0.0 && px < f.image.x && py < f.image.y);
    uint32_t tx = uint32_t(px) / kTileSize, ty = uint32_t(py) / kTileSize;
    return classes[size_t(ty) * imageTiles(f.image.x, f.image.y).x1 + tx];
}

// A box on a floor, lit from one side: the box's tiles and the tiles of its shadow need the
// grid; the floor elsewhere needs only the planes; the sky needs nothing.
TEST(TracedTiles, TilesSeeingOnlyTheFloorOutsideTheShadowNeedNoGrid) {
    Camera camera;
    camera.eye = {0.0, 3.0, 8.0};
    camera.look = {0.0, 0.5, 0.0};
    camera.fovDegrees = 50.0f;
    SceneExtent extent;
    extent.boxes.push_back(boxOf({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}));
    extent.planes.push_back(glm::dvec4(0.0, 1.0, 0.0, 0.0));
    Light light;
    light.position = {-4.0, 4.0, 0.0};
    std::optional<std::vector<Aabb>> shadows =
        planeShadowBoxes(extent.boxes, extent.planes, {light});
    ASSERT_TRUE(shadows.has_value());
    gpu::GpuFrameParams frame = frameFor(camera, 256, 192);
    std::vector<uint8_t> classes = tileClasses(frame, extent, *shadows);
    EXPECT_EQ(classAt(classes, frame, {0.0, 0.5, 0.5}), kTileFull);        // the box
    EXPECT_EQ(classAt(classes, frame, {1.8, 0.0, 0.3}), kTileFull);        // its shadow
    EXPECT_EQ(classAt(classes, frame, {-3.0, 0.0, 3.0}), kTilePlanesOnly); // the floor
    EXPECT_EQ(classAt(classes, frame, {2.5, 0.0, 3.5}), kTilePlanesOnly);
    EXPECT_EQ(classAt(classes, frame, {-2.5, 0.0, -2.0}), kTilePlanesOnly); // towards the light
    EXPECT_EQ(classAt(classes, frame, {0.0, 5.0, -40.0}), kTileBackground); // the sky
    // The same with no shadow boxes (no shadows traced): the shadow's tiles need no grid.
    std::vector<uint8_t> unshadowed = tileClasses(frame, extent, {});
    EXPECT_EQ(classAt(unshadowed, frame, {1.8, 0.0, 0.3}), kTilePlanesOnly);
    EXPECT_EQ(classAt(unshadowed, frame, {0.0, 0.5, 0.5}), kTileFull);
}

bool segmentMeetsSphere(glm::dvec3 o, glm::dvec3 a, const Sphere &s) {
    glm::dvec3 d = a - o, oc = o - s.center;
    double qa = glm::dot(d, d), qb = glm::dot(oc, d), qc = glm::dot(oc, oc) - s.radius * s.radius;
    double disc = qb * qb - qa * qc;
    if (disc < 0.0)
        return false;
    double root = std::sqrt(disc), t0 = (-qb - root) / qa, t1 = (-qb + root) / qa;
    return t1 > 0.0 && t0 < 1.0;
}

// A reflection off the floor that meets a box: the camera ray, continued through the floor,
// passes through the box's mirror image (grown for the reflected ray's offset origin).
TEST(TracedTiles, EveryReflectionThatMeetsABoxComesFromACameraRayThroughItsMirrorImage) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), zeroOne(0.0, 1.0);
    size_t reflections = 0;
    for (int trial = 0; trial < 40; ++trial) {
        glm::dvec3 n = glm::normalize(glm::dvec3(0.3 * unit(rng), 1.0, 0.3 * unit(rng)));
        glm::dvec4 plane(n, 0.5 * unit(rng));
        std::vector<Aabb> boxes;
        for (int b = 0; b < 2; ++b) {
            glm::dvec3 c(3.0 * unit(rng), 0.6 + 2.0 * zeroOne(rng), 3.0 * unit(rng));
            glm::dvec3 half(0.05 + 0.5 * zeroOne(rng));
            boxes.push_back(boxOf(c - half, c + half));
        }
        glm::dvec3 eye(6.0 * unit(rng), 2.0 + 3.0 * zeroOne(rng), 8.0 + 40.0 * zeroOne(rng));
        std::vector<Aabb> mirrors = planeMirrorBoxes(boxes, plane, eye, 0.0);
        ASSERT_EQ(mirrors.size(), boxes.size());
        for (int k = 0; k < 4000; ++k) {
            // Aimed at the mirror image of a point in or near a box, on its faces for a quarter
            // of them (where the margin matters), pushed out by up to a few offsets.
            const Aabb &box = boxes[size_t(k) % boxes.size()];
            glm::dvec3 size = box.max - box.min;
            glm::dvec3 b =
                box.min + size * glm::dvec3(1.2 * zeroOne(rng) - 0.1, 1.2 * zeroOne(rng) - 0.1,
                                            1.2 * zeroOne(rng) - 0.1);
            if (k % 4 == 0) {
                int axis = int(rng() % 3);
                b[axis] = (rng() % 2 ? box.max[axis] : box.min[axis]) +
                          unit(rng) * 4.0 * PRISM_OFFSET_RELATIVE * glm::length(eye);
            }
            glm::dvec3 image = b - n * (2.0 * (glm::dot(n, b) - plane.w));
            glm::dvec3 d = glm::normalize(image - eye);
            double t = (plane.w - glm::dot(n, eye)) / glm::dot(n, d);
            if (!(t > 0.0))
                continue;
            glm::dvec3 hit = eye + t * d;
            double e = PRISM_OFFSET_RELATIVE *
                       std::max({std::abs(hit.x), std::abs(hit.y), std::abs(hit.z)});
            glm::dvec3 origin = hit + e * n, reflected = d - 2.0 * glm::dot(d, n) * n;
            bool meets = false;
            for (const Aabb &box : boxes)
                meets = meets || hitsBox(origin, reflected, box.min, box.max);
            if (!meets)
                continue;
            ++reflections;
            bool seen = false;
            for (const Aabb &m : mirrors)
                seen = seen || hitsBox(eye, d, m.min, m.max);
            ASSERT_TRUE(seen) << "trial " << trial << ": a reflection meets a box, but its camera "
                              << "ray passes through no mirror image";
        }
    }
    EXPECT_GT(reflections, size_t(40000));
}

// `count` spheres of radius 0.15 to 0.15 + `spread` over [-3, 3]^2 of the floor y = 0, each
// clear of it by up to 1.2.
void addSpheresAboveTheFloor(Scene &scene, std::mt19937 &rng, int count, double spread) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), zeroOne(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
        double r = 0.15 + spread * zeroOne(rng);
        scene.spheres.push_back(
            Sphere{{3.0 * unit(rng), r + 1.2 * zeroOne(rng), 3.0 * unit(rng)}, float(r), 0});
    }
}

// Calls visit(origin, dir) for one camera ray through each pixel of the tiles left without the
// grid (at a random place in the pixel, as the shader's jitter could put it), once it has
// checked that the ray meets none of the scene's spheres.
template <typename Visit>
void forEachPlaneTileRay(const gpu::GpuFrameParams &frame, const std::vector<uint8_t> &classes,
                         const Scene &scene, std::mt19937 &rng, Visit visit) {
    std::uniform_real_distribution<float> zeroOne(0.0f, 1.0f);
    uint32_t tilesX = imageTiles(frame.image.x, frame.image.y).x1;
    for (uint32_t py = 0; py < frame.image.y; ++py)
        for (uint32_t px = 0; px < frame.image.x; ++px) {
            if (classes[size_t(py / kTileSize) * tilesX + px / kTileSize] != kTilePlanesOnly)
                continue;
            glm::dvec3 o, d;
            cameraRay(frame, glm::vec2(px, py) + glm::vec2(zeroOne(rng), zeroOne(rng)), o, d);
            for (const Sphere &s : scene.spheres)
                ASSERT_FALSE(segmentMeetsSphere(o, o + 1e4 * d, s))
                    << "pixel " << px << "," << py << " was left without the grid";
            visit(o, d);
        }
}

// End to end, with real geometry: in every tile left without the grid, no camera ray meets a
// sphere, and no shadow ray from its floor hits (from any point of a spherical light, leaving
// from the offset origin as the shader does) meets one either.
TEST(TracedTiles, NoRayOfATileWithoutTheGridMeetsTheGridsGeometry) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), zeroOne(0.0, 1.0);
    size_t planeTiles = 0, tiles = 0, shadowRays = 0;
    for (int trial = 0; trial < 12; ++trial) {
        Scene scene = sceneWithDefaultMaterial();
        scene.planes.push_back(Plane{{0.0, 0.0, 0.0}, {0.0f, 1.0f, 0.0f}, 0});
        addSpheresAboveTheFloor(scene, rng, 6, 0.4);
        scene.lights.push_back(Light{{6.0 * unit(rng), 5.0 + 2.0 * zeroOne(rng), 6.0 * unit(rng)},
                                     {1.0f, 1.0f, 1.0f},
                                     trial % 2 == 0 ? 0.0f : 0.7f});
        scene.camera.eye = {7.0 * unit(rng), 2.0 + 4.0 * zeroOne(rng), 9.0};
        scene.camera.look = {unit(rng), 0.5, unit(rng)};
        scene.camera.fovDegrees = 60.0f;
        Grid grid = buildGrid(scene);
        SceneExtent extent = sceneExtent(scene, grid);
        std::optional<std::vector<Aabb>> shadows =
            planeShadowBoxes(extent.boxes, extent.planes, scene.lights);
        ASSERT_TRUE(shadows.has_value());
        gpu::GpuFrameParams frame = frameFor(scene.camera, 96, 72);
        std::vector<uint8_t> classes = tileClasses(frame, extent, *shadows);
        const Light &light = scene.lights[0];
        forEachPlaneTileRay(frame, classes, scene, rng, [&](glm::dvec3 o, glm::dvec3 d) {
            if (d.y >= 0.0)
                return;
            glm::dvec3 hit = o + d * (-o.y / d.y);
            double e = PRISM_OFFSET_RELATIVE *
                       std::max({std::abs(hit.x), std::abs(hit.y), std::abs(hit.z)});
            glm::dvec3 origin = hit + glm::dvec3(0.0, e, 0.0);
            for (int k = 0; k < 4; ++k) {
                glm::dvec3 u = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)) + 1e-9);
                glm::dvec3 target = light.position + double(light.radius) * u;
                ++shadowRays;
                for (const Sphere &s : scene.spheres)
                    ASSERT_FALSE(segmentMeetsSphere(origin, target, s))
                        << "trial " << trial
                        << ": a tile left without the grid, but a shadow ray meets a sphere";
            }
        });
        planeTiles += size_t(std::count(classes.begin(), classes.end(), kTilePlanesOnly));
        tiles += classes.size();
    }
    // Not vacuous: a good share of the tiles went without the grid, and were checked.
    EXPECT_GT(double(planeTiles) / double(tiles), 0.2);
    EXPECT_GT(shadowRays, size_t(20000));
}

// The seed scenes' room: a mirror floor and two matte walls. In every tile left without the
// grid, no camera ray, no shadow ray from its plane hit, no reflection off the floor, and no
// shadow ray from where that reflection meets a wall, meets a sphere.
TEST(TracedTiles, NoRayOfAMirrorRoomsTileWithoutTheGridMeetsTheGridsGeometry) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), zeroOne(0.0, 1.0);
    size_t planeTiles = 0, tiles = 0, wallReflections = 0;
    auto offsetFrom = [](glm::dvec3 p, glm::dvec3 facing) {
        return p + PRISM_OFFSET_RELATIVE * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) *
                       facing;
    };
    for (int trial = 0; trial < 12; ++trial) {
        Scene scene = sceneWithDefaultMaterial();
        uint32_t mirror = addMaterial(scene, "mirror", {0.6f, 0.6f, 0.6f}, 0.3f);
        scene.planes.push_back(Plane{{0.0, 0.0, 0.0}, {0.0f, 1.0f, 0.0f}, mirror});
        scene.planes.push_back(Plane{{0.0, 0.0, -4.0}, {0.0f, 0.0f, 1.0f}, 0});
        scene.planes.push_back(Plane{{-4.5, 0.0, 0.0}, {1.0f, 0.0f, 0.0f}, 0});
        addSpheresAboveTheFloor(scene, rng, 5, 0.35);
        // In front of the spheres as the walls see it (nearer the camera): bounded shadows.
        scene.lights.push_back(
            Light{{4.6 + 2.0 * zeroOne(rng), 5.0 + 2.0 * zeroOne(rng), 4.6 + 2.0 * zeroOne(rng)},
                  {1.0f, 1.0f, 1.0f},
                  trial % 2 == 0 ? 0.0f : 0.5f});
        scene.camera.eye = {5.0 * unit(rng), 1.5 + 3.0 * zeroOne(rng), 9.0};
        scene.camera.look = {unit(rng), 0.8, unit(rng)};
        scene.camera.fovDegrees = 60.0f;
        Grid grid = buildGrid(scene);
        SceneExtent extent = sceneExtent(scene, grid);
        std::optional<PlaneTileGuards> guards =
            planeTileGuards(extent.boxes, extent.planes, scene.lights, true, size_t(0));
        ASSERT_TRUE(guards.has_value());
        gpu::GpuFrameParams frame = frameFor(scene.camera, 96, 72);
        std::vector<uint8_t> classes = tileClasses(frame, extent, needGridBoxes(*guards, frame));
        const Light &light = scene.lights[0];
        auto nearestPlane = [&](glm::dvec3 o, glm::dvec3 d, size_t skip, double &t) {
            size_t best = SIZE_MAX;
            t = INFINITY;
            for (size_t k = 0; k < extent.planes.size(); ++k) {
                glm::dvec3 n(extent.planes[k]);
                double tk = (extent.planes[k].w - glm::dot(n, o)) / glm::dot(n, d);
                if (k != skip && tk > 0.0 && tk < t) {
                    t = tk;
                    best = k;
                }
            }
            return best;
        };
        auto expectUnshadowed = [&](glm::dvec3 p, glm::dvec3 n, const char *what) {
            for (int s = 0; s < 3; ++s) {
                glm::dvec3 u = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)) + 1e-9);
                glm::dvec3 target = light.position + double(light.radius) * u;
                if (glm::dot(target - p, n) <= 0.0)
                    continue; // the light is behind the surface: no shadow ray
                for (const Sphere &sphere : scene.spheres)
                    ASSERT_FALSE(segmentMeetsSphere(offsetFrom(p, n), target, sphere))
                        << "trial " << trial << ": " << what;
            }
        };
        forEachPlaneTileRay(frame, classes, scene, rng, [&](glm::dvec3 o, glm::dvec3 d) {
            double t;
            size_t k = nearestPlane(o, d, SIZE_MAX, t);
            if (k == SIZE_MAX)
                return;
            glm::dvec3 hit = o + t * d, n(extent.planes[k]);
            if (glm::dot(n, d) > 0.0)
                n = -n; // the side the camera sees
            expectUnshadowed(hit, n, "a shadow ray from a plane hit meets a sphere");
            if (k != 0)
                return; // a matte wall: nothing more
            glm::dvec3 r = d - 2.0 * glm::dot(d, n) * n, from = offsetFrom(hit, n);
            for (const Sphere &s : scene.spheres)
                ASSERT_FALSE(segmentMeetsSphere(from, from + 1e4 * r, s))
                    << "trial " << trial << ": a reflection off the floor meets a sphere";
            double tw;
            size_t w = nearestPlane(from, r, 0, tw);
            if (w == SIZE_MAX)
                return;
            glm::dvec3 q = from + tw * r, nw(extent.planes[w]);
            if (glm::dot(nw, r) > 0.0)
                nw = -nw;
            ++wallReflections;
            expectUnshadowed(q, nw, "a reflected wall point's shadow ray meets a sphere");
        });
        planeTiles += size_t(std::count(classes.begin(), classes.end(), kTilePlanesOnly));
        tiles += classes.size();
    }
    EXPECT_GT(double(planeTiles) / double(tiles), 0.1);
    EXPECT_GT(wallReflections, size_t(5000)) << "reflections that meet a wall were checked";
}

class TracedTilesRender : public GpuTest {
protected:
    // The frame culled and traced in full: every pixel, AOV and ray count the same.
    void expectCullingChangesNoPixel(const Scene &scene) {
        TracerOptions culled, full;
        culled.writeAov = full.writeAov = true;
        full.cullMissTiles = false;
        GpuRender a = renderGpu(context(), scene, 70, 50, 2, 3, GridOptions{}, culled);
        GpuRender b = renderGpu(context(), scene, 70, 50, 2, 3, GridOptions{}, full);
        expectSameFrame(a, b);
    }
};

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
    for (const Scene *s : {&scene, &withSky, &parallel, &floating})
        expectCullingChangesNoPixel(*s);
    // And the floating scene did leave tiles to the background.
    Scene centred = floating;
    centerOnCamera(centred);
    Grid grid = buildGrid(centred);
    EXPECT_LT(
        tracedShare(tilesThatMayHit(frameFor(centred.camera, 70, 50), sceneExtent(centred, grid))),
        0.9);
}

// A tracer given the scene's extent (TracerOptions::extent, as prepareScene finds it or reads it
// from the cache) traces by that extent: the one sceneExtent finds gives the same frame as none
// given, and an extent with nothing in it leaves every tile to the background, so the given one
// is the one used.
TEST_F(TracedTilesRender, AGivenExtentIsTheOneTracedBy) {
    Scene scene = stabilityScene();
    scene.planes.clear(); // the floor's tiles would be traced by any extent with its plane
    centerOnCamera(scene);
    Grid grid = buildGrid(scene);
    SceneExtent found = sceneExtent(scene, grid);
    SceneExtent nothing;
    auto render = [&](const SceneExtent *extent) {
        TracerOptions options;
        options.extent = extent;
        RayTracer tracer(context(), scene, grid, 70, 50, options);
        GpuRender out;
        out.frame = tracer.renderFrame(scene.camera, 1);
        out.image = tracer.readback(1);
        return out;
    };
    GpuRender own = render(nullptr), given = render(&found), empty = render(&nothing);
    expectSameFrame(given, own);
    EXPECT_NE(empty.image.rgba, own.image.rgba);
    EXPECT_EQ(empty.frame.rays.shadow, 0u) << "no tile traced the geometry";
    EXPECT_GT(own.frame.rays.shadow, 0u);
    // An extent is found with one start-box cap: a tracer asked for another finds its own.
    TracerOptions capped;
    capped.maxStartBoxes = 64;
    capped.extent = &nothing;
    RayTracer tracer(context(), scene, grid, 70, 50, capped);
    tracer.renderFrame(scene.camera, 1);
    EXPECT_EQ(tracer.readback(1).rgba, own.image.rgba);
}

// The eye inside a large sphere (its blocks there left out of the extent: rays reach them only
// through the shell), and inside a glass one among others: the same frame culled as traced in
// full, both cameras.
TEST_F(TracedTilesRender, AnEyeInsideASphereChangesNoPixel) {
    Scene scene = stabilityScene();
    scene.camera.eye = {0.0, 1.5, 4.0};
    scene.camera.look = {0.0, 1.0, 0.0};
    Sphere room = scene.spheres.front();
    room.center = {0.3, 1.2, 3.5};
    room.radius = 12.0f;
    Scene inRoom = scene;
    inRoom.spheres.push_back(room);
    Scene inGlass = scene;
    Sphere glass = room;
    glass.radius = 1.0f;
    glass.material = addMaterial(inGlass, opticalMaterial("glass", 0.1f, 0.9f, 1.5f));
    inGlass.spheres.push_back(glass);
    Scene parallel = inGlass;
    parallel.camera.orthoHeight = 4.0f;
    for (const Scene *s : {&inRoom, &inGlass, &parallel})
        expectCullingChangesNoPixel(*s);
}

// A tracer keeps a frame's tile lists while the camera rests (the viewer's progressive
// samples, one submission each): it makes them once per camera, and one that samples a camera,
// a second one looking elsewhere, then the first again gives each image as a new tracer's
// frame; the two cameras do need different tiles.
TEST_F(TracedTilesRender, KeptTileListsFollowTheCamera) {
    Scene scene = stabilityScene();
    scene.camera.eye = {0.0, 3.0, 9.0};
    scene.camera.look = {0.0, 3.5, 0.0}; // sky above the horizon: background tiles
    centerOnCamera(scene);               // as renderGpu does; both cameras share these coordinates
    Grid grid = buildGrid(scene);
    Camera first = scene.camera, aside = first;
    aside.look = first.eye + glm::dvec3(-3.0, -1.5, -2.0); // the objects off to one side
    TracerOptions options;
    options.writeAov = true;
    options.maxDepth = 3;
    const uint32_t spp = 3;
    RayTracer kept(context(), scene, grid, 70, 50, options);
    vk::CommandRunner runner(context());
    std::vector<std::vector<uint8_t>> classes;
    for (const Camera *camera : {&first, &aside, &first}) {
        uint64_t made = kept.tileListsMade();
        for (uint32_t sample = 0; sample < spp; ++sample)
            runner.run([&](VkCommandBuffer commands) {
                kept.recordSamples(commands, *camera, sample, 1, spp);
            });
        EXPECT_EQ(kept.tileListsMade(), made + 1) << "the lists once for a resting camera";
        TracedImage image = kept.readback(spp);
        classes.push_back(kept.lastTileClasses());
        RayTracer fresh(context(), scene, grid, 70, 50, options);
        fresh.renderFrame(*camera, spp);
        TracedImage expected = fresh.readback(spp);
        EXPECT_EQ(image.rgba, expected.rgba);
        EXPECT_EQ(image.depth, expected.depth);
        EXPECT_EQ(image.normal, expected.normal);
        EXPECT_EQ(classes.back(), fresh.lastTileClasses());
    }
    EXPECT_NE(classes[0], classes[1]);
    EXPECT_EQ(classes[0], classes[2]);
}

// Ray counts: a workgroup counts its tile's camera rays at once, from the tile's place, and each
// lane its own shadow and secondary rays (shaders/trace.comp, addCounts). On an image that ends
// in mid-tile both ways, with every tile class and three samples, the camera rays are one per
// pixel and sample, and all counts are those of resumable tracing, which counts each pixel's
// camera ray where its sample finishes.
TEST_F(TracedTilesRender, RayCountsOnImagesThatEndInMidTile) {
    Scene scene = stabilityScene(); // a reflective floor, spheres, a mesh
    scene.camera.eye = {0.0, 3.0, 9.0};
    scene.camera.look = {0.0, 3.5, 0.0}; // sky above the horizon: background tiles too
    const uint32_t width = 45, height = 27, spp = 3;
    TracerOptions tiled, resumable;
    resumable.resumable = true;
    GpuRender a = renderGpu(context(), scene, width, height, spp, 3, GridOptions{}, tiled);
    GpuRender b = renderGpu(context(), scene, width, height, spp, 3, GridOptions{}, resumable);
    EXPECT_EQ(a.frame.rays.primary, uint64_t(width) * height * spp);
    EXPECT_GT(a.frame.rays.shadow, 0u);
    EXPECT_GT(a.frame.rays.secondary, 0u);
    EXPECT_GT(a.frame.tiles[0], 0u); // the full tracer's tiles
    EXPECT_GT(a.frame.tiles[2], 0u); // the background's
    expectSameFrame(a, b);
}

// Camera rays that start their walk at their tile's start distance find what a walk from the
// grid's entry finds: every pixel, AOV and ray count the same, on both grids, both cameras, at
// depth 1 and with reflections, with a mesh (the teapot, whose grid is adaptive) and spheres.
TEST_F(TracedTilesRender, TileStartsChangeNoPixel) {
    Scene scene = stabilityScene();
    scene.camera.eye = {0.0, 3.0, 9.0};
    scene.camera.look = {0.0, 1.0, 0.0};
    Scene parallel = scene;
    parallel.camera.orthoHeight = 5.0f;
    Scene teapot = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "teapot.scene");
    for (const Scene *s : {&scene, &parallel, &teapot})
        for (const char *grid : {"regular", "adaptive"})
            for (uint32_t depth : {1u, 3u}) {
                SCOPED_TRACE(std::string(grid) + " depth " + std::to_string(depth));
                TracerOptions from, entry;
                from.writeAov = entry.writeAov = true;
                entry.tileStarts = false;
                GridOptions g = parseGridOption(grid);
                GpuRender a = renderGpu(context(), *s, 96, 72, 1, depth, g, from);
                GpuRender b = renderGpu(context(), *s, 96, 72, 1, depth, g, entry);
                expectSameFrame(a, b);
            }
}

// More tiles than one row of workgroups may hold (65,535), in one dispatch: every pixel is still
// traced once, and no dispatch exceeds the device's limit (validation is on).
// The AOV image starts unwritten, so a tile left out shows as a depth that is neither a hit's
// distance nor a miss's infinity.
TEST_F(TracedTilesRender, ImagesOfMoreThan65535TilesAreCovered) {
    Scene scene = stabilityScene();
    TracerOptions options;
    options.writeAov = true;
    options.cullMissTiles = false;              // so that one dispatch takes them all
    const uint32_t width = 2048, height = 2056; // 256 x 257 tiles
    ASSERT_GT(imageTiles(width, height).width() * imageTiles(width, height).height(), 65535u);
    GpuRender render = renderGpu(context(), scene, width, height, 1, 1, GridOptions{}, options);
    size_t misses = 0, bad = 0;
    for (float depth : render.image.depth) {
        misses += std::isinf(depth) ? 1 : 0;
        bad += (std::isinf(depth) || depth > 0.0f) ? 0 : 1;
    }
    EXPECT_EQ(bad, 0u);
    EXPECT_GT(misses, 0u);
    EXPECT_EQ(render.frame.rays.primary, uint64_t(width) * height);
}

// Tiles traced without the grid change no pixel, AOV or ray count: at depth 1 under a reflective
// floor (no secondary rays), at depth 3 under a matte one, with a soft shadow, two lights and a
// parallel camera, and under the reflective floor at depth 3 (its one mirror plane's
// reflections followed as mirror images), with both cameras and with two matte walls. Where a
// reflection could meet a second mirror, or the floor refracts, no tile goes without the grid.
TEST_F(TracedTilesRender, TilesWithoutTheGridChangeNoPixel) {
    Scene shiny = stabilityScene(); // the floor reflects
    Scene shinyParallel = shiny;
    shinyParallel.camera.orthoHeight = 6.0f;
    shinyParallel.lights[0].radius = 0.4f;
    Scene twoMirrors = shiny;
    twoMirrors.planes.push_back(
        Plane{{0.0, 0.0, -4.0}, {0.0f, 0.0f, 1.0f}, shiny.planes[0].material});
    Scene mirrorAndWalls = shiny; // the seed scenes' room: a mirror floor, two matte walls
    uint32_t wall = addMaterial(mirrorAndWalls, "wall", {0.75f, 0.72f, 0.68f});
    mirrorAndWalls.planes.push_back(Plane{{0.0, 0.0, -3.0}, {0.0f, 0.0f, 1.0f}, wall});
    mirrorAndWalls.planes.push_back(Plane{{-3.5, 0.0, 0.0}, {1.0f, 0.0f, 0.0f}, wall});
    // A ball high before the back wall, lit from the front: its shadow on the wall, seen in the
    // floor, lies away from the ball's own reflection and from its shadow on the floor.
    Scene wallShadow = sceneWithDefaultMaterial();
    wallShadow.planes.push_back(Plane{{0.0, 0.0, 0.0},
                                      {0.0f, 1.0f, 0.0f},
                                      addMaterial(wallShadow, "floor", {0.6f, 0.6f, 0.6f}, 0.5f)});
    wallShadow.planes.push_back(Plane{{0.0, 0.0, -4.0}, {0.0f, 0.0f, 1.0f}, 0});
    wallShadow.spheres.push_back(Sphere{{0.0, 2.0, -2.0}, 0.3f, 0});
    wallShadow.lights.push_back(Light{{0.0, 3.0, 6.0}, {1.0f, 1.0f, 1.0f}, 0.0f});
    wallShadow.camera.eye = {0.0, 1.5, 8.0};
    wallShadow.camera.look = {0.0, 0.8, -4.0};
    wallShadow.camera.fovDegrees = 40.0f;
    Scene glassFloor = shiny;
    glassFloor.materials[glassFloor.planes[0].material].transmit = 0.5f;
    Scene matte = shiny;
    matte.materials[matte.planes[0].material].reflect = 0.0f;
    Scene soft = matte;
    soft.lights[0].radius = 0.5f;
    Scene twoLights = matte;
    twoLights.lights.push_back(Light{{-5.0, 4.0, 2.0}, {0.5f, 0.5f, 0.5f}, 0.0f});
    Scene parallel = matte;
    parallel.camera.orthoHeight = 6.0f;
    struct Case {
        const Scene *scene;
        uint32_t depth;
        bool planeTiles;
    };
    for (Case c :
         {Case{&shiny, 1, true}, Case{&shiny, 3, true}, Case{&shinyParallel, 3, true},
          Case{&mirrorAndWalls, 3, true}, Case{&wallShadow, 2, true}, Case{&twoMirrors, 3, false},
          Case{&twoMirrors, 1, true}, Case{&glassFloor, 3, false}, Case{&matte, 3, true},
          Case{&soft, 2, true}, Case{&twoLights, 2, true}, Case{&parallel, 2, true}}) {
        TracerOptions with, without;
        with.writeAov = without.writeAov = true;
        without.cullPlaneTiles = false;
        GpuRender a = renderGpu(context(), *c.scene, 96, 72, 2, c.depth, GridOptions{}, with);
        GpuRender b = renderGpu(context(), *c.scene, 96, 72, 2, c.depth, GridOptions{}, without);
        expectSameFrame(a, b);
        EXPECT_EQ(a.frame.tiles[1] > 0, c.planeTiles) << "depth " << c.depth;
        EXPECT_EQ(b.frame.tiles[1], 0u);
        EXPECT_EQ(a.frame.tiles[0] + a.frame.tiles[1] + a.frame.tiles[2], 12u * 9u);
    }
}

} // namespace
} // namespace prism::test
