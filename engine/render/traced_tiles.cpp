#include "render/traced_tiles.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>

#include "accel/finite_primitives.h"
#include "core/parallel_for.h"

namespace prism {
namespace {

// Relative margin of every sign test below: far above the float rounding of the shader's ray
// and of the scene's float copy (a few 1e-7), far below the pixel of margin round each tile
// (1e-3 of the image at 1024).
constexpr double kEpsilon = 1e-5;

// Image-plane coordinates (x right, y up, [-1, 1] across the image) as trace.comp's cameraRay
// has them for a sample position in pixels, and back.
double imageX(double px, double width) {
    return 2.0 * px / width - 1.0;
}
double imageY(double py, double height) {
    return 1.0 - 2.0 * py / height;
}

struct TileSpan {
    double x0, x1, y0, y1; // image-plane coordinates, with a pixel's margin
};

TileSpan tileSpan(uint32_t tx, uint32_t ty, double width, double height) {
    // Sample positions of the tile's pixels lie in [8 t, 8 t + 8]; one pixel more each side.
    double px0 = double(tx * kTileSize) - 1.0, px1 = double(tx * kTileSize + kTileSize) + 1.0;
    double py0 = double(ty * kTileSize) - 1.0, py1 = double(ty * kTileSize + kTileSize) + 1.0;
    return {imageX(px0, width), imageX(px1, width), imageY(py1, height), imageY(py0, height)};
}

struct RayFrame {
    glm::dvec3 eye, forward, du, dv;
    bool parallel;
    glm::dmat3 toImage;    // p - eye -> (a, b, c) with p - eye = a du + b dv + c forward
    glm::dmat3 absToImage; // toImage's entries' magnitudes
};

// A ray o + t d (t > 0) hits the plane n.p = w where w - n.o and n.d have the same sign. The
// tile's rays miss it where every one has them of opposite signs, clearly: the shader's
// rounding could flip a sign that is nearly zero.
bool opposite(double g, double gScale, double s, double sScale) {
    return std::abs(g) > kEpsilon * gScale && std::abs(s) > kEpsilon * sScale && g * s < 0.0;
}

bool tileMayHitAPlane(const RayFrame &cam, const TileSpan &span,
                      const std::vector<glm::dvec4> &planes) {
    const double xs[2] = {span.x0, span.x1}, ys[2] = {span.y0, span.y1};
    for (const glm::dvec4 &plane : planes) {
        glm::dvec3 n(plane);
        bool missed = true;
        for (double x : xs)
            for (double y : ys) {
                glm::dvec3 o = cam.eye, d = cam.forward + x * cam.du + y * cam.dv;
                if (cam.parallel) {
                    o = cam.eye + x * cam.du + y * cam.dv;
                    d = cam.forward;
                }
                missed =
                    missed && opposite(plane.w - glm::dot(n, o), std::abs(plane.w) + glm::length(o),
                                       glm::dot(n, d), glm::length(d));
            }
        if (!missed)
            return true;
    }
    return false;
}

// Boxes are projected a batch at a time: the arithmetic runs in plain loops over arrays, which
// the compiler turns into SIMD instructions, and only the loops over each box's tiles that
// follow branch. Tens of thousands of boxes a frame, on the host while the device waits.
constexpr size_t kBatch = 128;

// What the tiles need of each box of a batch.
struct ProjectedBoxes {
    // The tiles where camera rays may meet the box, [x0, x1) x [y0, y1) (empty where none may:
    // x0 = x1 = 0), and whether that is every tile because the box reaches back to the eye's
    // plane (a perspective camera's box so near would project far off or flipped).
    int32_t x0[kBatch], x1[kBatch], y0[kBatch], y1[kBatch];
    int32_t all[kBatch];
    // A distance along the rays before which none meets the box, as a float rounded down (the
    // shader's t is one), below kNoBoxAhead (which marks a tile that sees no box).
    float start[kBatch];
};

// Box i's distance rounded down to a float, and below kNoBoxAhead.
const float kFarthestStart = std::nextafter(kNoBoxAhead, 0.0f);
float startBelow(double d) {
    float start = float(d);
    // Where the conversion rounded up, the next float towards 0: a positive float's bits less
    // one (std::nextafter's answer, without its call in the batch's loop; +inf gives the
    // largest float).
    if (double(start) > d)
        start = std::bit_cast<float>(std::bit_cast<uint32_t>(start) - 1u);
    return std::min(start, kFarthestStart);
}

// Projects boxes[0, count) (count <= kBatch). Each box is first grown by a relative margin, so
// that rounding in the host's own arithmetic cannot cut it.
//
// Where a box is seen: perspective rays leave the eye along forward + x du + y dv, so a point at
// (a, b, c) is seen at (a / c, b / c) when c > 0; parallel rays leave (x, y) along forward, so
// it is seen at (a, b). The box's (a, b, c) lie in centre +- extent, with extent = |toImage|
// half-size (the exact ranges of a linear map over a box), and the rectangle is that of a / c
// over those ranges: for fixed a, a / c is monotonic in c, so its extremes are at the ranges'
// ends. Two divisions a box where projecting its eight corners took eight; the rectangle is the
// corners' one grown by what the box's depth range adds (c's range against c: under 1% for the
// start blocks of a scene in view), which only ever adds tiles.
//
// How far rays go before they may meet it: perspective rays leave the eye with unit directions,
// so that is the distance from the eye, at least the box's. Parallel rays leave the image plane
// along forward: a point's depth beyond that plane, less what du and dv add to it for a camera
// whose axes are not quite square (samples lie within a pixel of the image: |x|, |y| < 1.1 for
// any image of 20 pixels).
template <bool Parallel>
[[gnu::always_inline]] inline void projectBoxes(const RayFrame &cam, double width, double height,
                                                const Aabb *boxes, size_t count,
                                                ProjectedBoxes &out) {
    double lx[kBatch], ly[kBatch], lz[kBatch], ux[kBatch], uy[kBatch], uz[kBatch];
    double nearC[kBatch], farC[kBatch], backLimit[kBatch], px0[kBatch], px1[kBatch], py0[kBatch],
        py1[kBatch], distance[kBatch];
    for (size_t i = 0; i < count; ++i) {
        lx[i] = boxes[i].min.x, ly[i] = boxes[i].min.y, lz[i] = boxes[i].min.z;
        ux[i] = boxes[i].max.x, uy[i] = boxes[i].max.y, uz[i] = boxes[i].max.z;
    }
    // Copied out of the camera, so that the stores below cannot be taken to change them.
    const glm::dmat3 m = cam.toImage, am = cam.absToImage;
    const glm::dvec3 eye = cam.eye, f = cam.forward, af = glm::abs(cam.forward);
    const double ff = glm::dot(f, f),
                 skew = 1.1 * (std::abs(glm::dot(cam.du, f)) + std::abs(glm::dot(cam.dv, f))) / ff;
    const double m00 = m[0][0], m10 = m[1][0], m20 = m[2][0], m01 = m[0][1], m11 = m[1][1],
                 m21 = m[2][1], m02 = m[0][2], m12 = m[1][2], m22 = m[2][2];
    const double n00 = am[0][0], n10 = am[1][0], n20 = am[2][0], n01 = am[0][1], n11 = am[1][1],
                 n21 = am[2][1], n02 = am[0][2], n12 = am[1][2], n22 = am[2][2];
    const TileRect image = imageTiles(uint32_t(width), uint32_t(height));
    const int32_t tilesX = int32_t(image.x1), tilesY = int32_t(image.y1);
    auto pad = [](double lo, double hi) {
        return kEpsilon * (std::abs(hi - lo) + std::abs(lo) + std::abs(hi)) + 1e-30;
    };
    for (size_t i = 0; i < count; ++i) {
        // Centre (from the eye) and half-size, padded.
        double cx = 0.5 * (lx[i] + ux[i]) - eye.x, cy = 0.5 * (ly[i] + uy[i]) - eye.y,
               cz = 0.5 * (lz[i] + uz[i]) - eye.z;
        double hx = 0.5 * (ux[i] - lx[i]) + pad(lx[i], ux[i]),
               hy = 0.5 * (uy[i] - ly[i]) + pad(ly[i], uy[i]),
               hz = 0.5 * (uz[i] - lz[i]) + pad(lz[i], uz[i]);
        double a = m00 * cx + m10 * cy + m20 * cz;
        double b = m01 * cx + m11 * cy + m21 * cz;
        double c = m02 * cx + m12 * cy + m22 * cz;
        double ea = n00 * hx + n10 * hy + n20 * hz;
        double eb = n01 * hx + n11 * hy + n21 * hz;
        double ec = n02 * hx + n12 * hy + n22 * hz;
        double a0 = a - ea, a1 = a + ea, b0 = b - eb, b1 = b + eb, c0 = c - ec, c1 = c + ec;
        double x0 = a0, x1 = a1, y0 = b0, y1 = b1;
        if constexpr (!Parallel) {
            double nearInverse = 1.0 / c0, farInverse = 1.0 / c1;
            x0 = std::min(a0 * nearInverse, a0 * farInverse);
            x1 = std::max(a1 * nearInverse, a1 * farInverse);
            y0 = std::min(b0 * nearInverse, b0 * farInverse);
            y1 = std::max(b1 * nearInverse, b1 * farInverse);
        }
        nearC[i] = c0;
        farC[i] = c1;
        backLimit[i] = kEpsilon * (std::max(std::abs(a0), std::abs(a1)) +
                                   std::max(std::abs(b0), std::abs(b1)) + c1);
        // The pixels whose sample positions may fall where the box is seen, with one more each
        // side (the tile span's margin).
        px0[i] = (x0 + 1.0) * 0.5 * width - 1.0;
        px1[i] = (x1 + 1.0) * 0.5 * width + 1.0;
        py0[i] = (1.0 - y1) * 0.5 * height - 1.0;
        py1[i] = (1.0 - y0) * 0.5 * height + 1.0;
        double t;
        if constexpr (Parallel) {
            t = (f.x * cx + f.y * cy + f.z * cz - (af.x * hx + af.y * hy + af.z * hz)) / ff - skew;
        } else {
            double gx = std::max(std::abs(cx) - hx, 0.0), gy = std::max(std::abs(cy) - hy, 0.0),
                   gz = std::max(std::abs(cz) - hz, 0.0);
            t = std::sqrt(gx * gx + gy * gy + gz * gz);
        }
        distance[i] = std::max(0.0, t * (1.0 - 1e-4));
    }
    // Their tiles: none where its rays miss the image or it lies behind the camera; all where
    // it reaches back to the eye's plane. In a loop of its own: one of mixed widths (double,
    // int, float) is not made SIMD.
    for (size_t i = 0; i < count; ++i) {
        // Bitwise, not short-circuit: a loop without branches is made SIMD.
        int32_t front = farC[i] > 0.0;
        int32_t all = int32_t(!Parallel) & front & int32_t(nearC[i] <= backLimit[i]);
        int32_t seen = front & int32_t(!(px1[i] < 0.0)) & int32_t(!(py1[i] < 0.0)) &
                       int32_t(!(px0[i] >= width)) & int32_t(!(py0[i] >= height));
        // Clamped before the conversion, so that a box off the image converts safely too.
        int32_t tx0 = int32_t(std::min(std::max(0.0, px0[i]), width)) / int32_t(kTileSize),
                ty0 = int32_t(std::min(std::max(0.0, py0[i]), height)) / int32_t(kTileSize),
                tx1 = std::min(
                    tilesX,
                    int32_t(std::max(0.0, std::min(width, px1[i]))) / int32_t(kTileSize) + 1),
                ty1 = std::min(
                    tilesY,
                    int32_t(std::max(0.0, std::min(height, py1[i]))) / int32_t(kTileSize) + 1);
        out.all[i] = all;
        out.x0[i] = all ? 0 : seen ? tx0 : 0;
        out.y0[i] = all ? 0 : seen ? ty0 : 0;
        out.x1[i] = all ? tilesX : seen ? tx1 : 0;
        out.y1[i] = all ? tilesY : seen ? ty1 : 0;
    }
    for (size_t i = 0; i < count; ++i)
        out.start[i] = startBelow(distance[i]);
}

// Compiled for AVX2 too, taken at load time where the processor has it (four doubles a vector
// against the x86-64 baseline's two): a bunny view's start distances on one core 0.39 -> 0.27 ms
// (2026-12-06). Not AVX-512: 0.03 ms more saved, against the risk of a lower clock for the
// tracer's threads on the same cores. Products are never fused into FMAs (-ffp-contract=off,
// engine/render/CMakeLists.txt), so both versions round alike: the same tiles and starts.
#if defined(__x86_64__) && !defined(__clang_analyzer__)
#define PRISM_SIMD_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define PRISM_SIMD_CLONES
#endif
PRISM_SIMD_CLONES void projectBoxes(const RayFrame &cam, double width, double height,
                                    const Aabb *boxes, size_t count, ProjectedBoxes &out) {
    if (cam.parallel)
        projectBoxes<true>(cam, width, height, boxes, count, out);
    else
        projectBoxes<false>(cam, width, height, boxes, count, out);
}

// Calls visit(tiles, all, start) for each of boxes[first, last) that camera rays of `frame` may
// meet (ProjectedBoxes), projecting a batch at a time, until visit returns false.
template <typename Visit>
void forEachSeenBox(const gpu::GpuFrameParams &frame, const RayFrame &cam,
                    const std::vector<Aabb> &boxes, size_t first, size_t last, Visit visit) {
    ProjectedBoxes projected;
    for (size_t batch = first; batch < last; batch += kBatch) {
        size_t count = std::min(kBatch, last - batch);
        projectBoxes(cam, frame.image.x, frame.image.y, &boxes[batch], count, projected);
        for (size_t i = 0; i < count; ++i) {
            if (projected.x0[i] >= projected.x1[i])
                continue; // unseen (a seen box has at least one tile: x1 > x0)
            TileRect tiles{uint32_t(projected.x0[i]), uint32_t(projected.y0[i]),
                           uint32_t(projected.x1[i]), uint32_t(projected.y1[i])};
            if (!visit(tiles, projected.all[i], projected.start[i]))
                return;
        }
    }
}

// Primitives from which occupiedBlocks marks its blocks on every core.
constexpr uint32_t kParallelBlocksPrimitives = 50'000;

// The blocks of a grid of at most `blocks` per axis over `grid`'s box that some primitive's
// surface may meet. Blocks inside a sphere are left out: any ray that reaches one crosses the
// sphere's surface first, in a nearer block, so the tiles and start distances stay bounds, and
// a scene of solid spheres has a shell of blocks instead of a volume (rand500: 31 ms of host
// time a frame for the start distances before, on two threads).
std::vector<Aabb> occupiedBlocks(const FinitePrimitives &primitives, const Grid &grid,
                                 uint32_t blocks) {
    // Cubic blocks, as many along the longest side as `blocks`.
    glm::dvec3 lo(grid.boundsMin), hi(grid.boundsMax), size = hi - lo;
    double side = std::max({size.x, size.y, size.z}) / blocks;
    glm::ivec3 res(1);
    if (side > 0.0)
        for (int a = 0; a < 3; ++a)
            res[a] = std::clamp(int(std::ceil(size[a] / side)), 1, int(blocks));
    glm::dvec3 block = size / glm::dvec3(res);
    auto blockOf = [&](const glm::dvec3 &p) {
        glm::ivec3 b;
        for (int a = 0; a < 3; ++a)
            b[a] = block[a] > 0.0
                       ? std::clamp(int(std::floor((p[a] - lo[a]) / block[a])), 0, res[a] - 1)
                       : 0;
        return b;
    };
    auto blockBox = [&](const glm::ivec3 &b) {
        Aabb box;
        box.min = lo + glm::dvec3(b) * block;
        for (int a = 0; a < 3; ++a)
            box.max[a] = b[a] + 1 == res[a] ? hi[a] : lo[a] + double(b[a] + 1) * block[a];
        return box;
    };
    // Each thread marks the blocks of its share of the primitives in its own array, merged
    // after: a set's union, the same whatever the threads (a pass over a 1M-triangle mesh took
    // 30-40 ms on one core, and the extent makes two or three). A small scene's pass takes
    // under a millisecond on one thread, while starting the pool's threads as OpenImageIO's
    // libraries load waits for the dynamic loader's lock: 150-200 ms for five spheres.
    size_t blockCount = size_t(res.x) * res.y * res.z;
    size_t shares = primitives.count() >= kParallelBlocksPrimitives ? parallelThreadCount() : 1;
    std::vector<std::vector<uint8_t>> marks(shares);
    parallelFor(shares, [&](size_t share) {
        std::vector<uint8_t> &occupied = marks[share];
        occupied.assign(blockCount, 0);
        uint32_t first = uint32_t(uint64_t(primitives.count()) * share / shares);
        uint32_t last = uint32_t(uint64_t(primitives.count()) * (share + 1) / shares);
        for (uint32_t id = first; id < last; ++id) {
            Aabb bounds = primitives.bounds(id);
            // Neighbouring blocks too where a bound lies on a face: the overlap test decides.
            glm::ivec3 b0 = blockOf(bounds.min - kEpsilon * glm::abs(block)),
                       b1 = blockOf(bounds.max + kEpsilon * glm::abs(block));
            for (int z = b0.z; z <= b1.z; ++z)
                for (int y = b0.y; y <= b1.y; ++y)
                    for (int x = b0.x; x <= b1.x; ++x) {
                        size_t index = size_t(x) + size_t(res.x) * (size_t(y) + size_t(res.y) * z);
                        if (occupied[index])
                            continue;
                        Aabb box = blockBox({x, y, z});
                        bool single = b0 == b1;
                        if (single || primitives.surfaceMayMeetBox(id, box.min, box.max))
                            occupied[index] = 1;
                    }
        }
    });
    std::vector<uint8_t> &occupied = marks[0];
    for (size_t share = 1; share < shares; ++share)
        for (size_t i = 0; i < blockCount; ++i)
            occupied[i] |= marks[share][i];
    std::vector<Aabb> boxes;
    for (int z = 0; z < res.z; ++z)
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x)
                if (occupied[size_t(x) + size_t(res.x) * (size_t(y) + size_t(res.y) * z)])
                    boxes.push_back(blockBox({x, y, z}));
    return boxes;
}

// occupiedBlocks by blocks per axis, each level made once: the extent's and the starts' share
// their coarse levels (a pass over every primitive each; tori of 1M triangles: 37 ms a pass).
class BlockLevels {
public:
    BlockLevels(const FinitePrimitives &primitives, const Grid &grid)
        : primitives_(primitives), grid_(grid) {}
    const std::vector<Aabb> &at(uint32_t blocks) {
        auto level = levels_.find(blocks);
        if (level == levels_.end())
            level = levels_.emplace(blocks, occupiedBlocks(primitives_, grid_, blocks)).first;
        return level->second;
    }

private:
    const FinitePrimitives &primitives_;
    const Grid &grid_;
    std::map<uint32_t, std::vector<Aabb>> levels_;
};

// The occupied blocks of the finest level, from `from` per axis halved down to 8 or doubled up
// to `finest`, with at most `maxBoxes` of them (8 per axis whatever the count). Every frame
// projects each box, so the count is what the host pays. A surface's blocks grow about
// fourfold a level, so a finer level is not made where this one has more than a quarter of
// `maxBoxes` (a scene whose blocks grow less, small scattered objects, may so stop a level
// short of the cap).
std::vector<Aabb> occupiedBlocksUpTo(BlockLevels &levels, uint32_t from, uint32_t finest,
                                     size_t maxBoxes) {
    uint32_t blocks = std::min(from, finest);
    while (blocks > 8 && levels.at(blocks).size() > maxBoxes)
        blocks /= 2;
    while (blocks < finest && 4 * levels.at(blocks).size() <= maxBoxes) {
        uint32_t next = std::min(2 * blocks, finest);
        if (levels.at(next).size() > maxBoxes)
            break;
        blocks = next;
    }
    return levels.at(blocks);
}

} // namespace

SceneExtent sceneExtent(const Scene &scene, const Grid &grid, size_t maxStartBoxes) {
    SceneExtent extent;
    for (const Plane &p : scene.planes) {
        glm::dvec3 n(p.normal);
        extent.planes.push_back(glm::dvec4(n, glm::dot(n, p.point)));
    }
    FinitePrimitives primitives(scene);
    if (primitives.count() == 0)
        return extent;
    BlockLevels levels(primitives, grid);
    extent.boxes = occupiedBlocksUpTo(levels, kExtentBlocks, kExtentBlocks, kMaxExtentBoxes);
    extent.startBoxes = occupiedBlocksUpTo(levels, kExtentBlocks, kStartBlocks, maxStartBoxes);
    return extent;
}

namespace {

RayFrame rayFrame(const gpu::GpuFrameParams &frame) {
    // The camera as the shader has it: the frame's floats.
    RayFrame cam{glm::dvec3(frame.eye), glm::dvec3(frame.forward),    glm::dvec3(frame.du),
                 glm::dvec3(frame.dv),  gpu::isParallelCamera(frame), glm::dmat3(1.0),
                 glm::dmat3(1.0)};
    cam.toImage = glm::inverse(glm::dmat3(cam.du, cam.dv, cam.forward));
    for (int column = 0; column < 3; ++column)
        cam.absToImage[column] = glm::abs(cam.toImage[column]);
    return cam;
}

// For each tile: 1 where a camera ray may pass through one of the boxes.
std::vector<uint8_t> tilesSeeingBoxes(const gpu::GpuFrameParams &frame, const RayFrame &cam,
                                      const std::vector<Aabb> &boxes) {
    TileRect image = imageTiles(frame.image.x, frame.image.y);
    uint32_t tilesX = image.x1, tilesY = image.y1;
    // Each box marks the tiles round its image: counted in a difference array (+1 at a
    // rectangle's corner, -1 past its ends), summed once at the end.
    std::vector<int32_t> marks(size_t(tilesX + 1) * (tilesY + 1), 0);
    auto at = [&](uint32_t x, uint32_t y) -> int32_t & {
        return marks[size_t(y) * (tilesX + 1) + x];
    };
    bool everyTile = false;
    forEachSeenBox(frame, cam, boxes, 0, boxes.size(), [&](const TileRect &t, bool all, float) {
        everyTile = all;
        at(t.x0, t.y0) += 1;
        at(t.x1, t.y0) -= 1;
        at(t.x0, t.y1) -= 1;
        at(t.x1, t.y1) += 1;
        return !all;
    });
    if (everyTile)
        return std::vector<uint8_t>(size_t(tilesX) * tilesY, 1);
    std::vector<uint8_t> seen(size_t(tilesX) * tilesY, 0);
    std::vector<int32_t> column(tilesX + 1, 0); // running sums down each column
    for (uint32_t ty = 0; ty < tilesY; ++ty) {
        int32_t row = 0;
        for (uint32_t tx = 0; tx < tilesX; ++tx) {
            column[tx] += at(tx, ty);
            row += column[tx];
            seen[size_t(ty) * tilesX + tx] = row > 0 ? 1 : 0;
        }
    }
    return seen;
}

bool tileSeesAPlane(const gpu::GpuFrameParams &frame, const RayFrame &cam,
                    const std::vector<glm::dvec4> &planes, uint32_t tx, uint32_t ty) {
    return !planes.empty() &&
           tileMayHitAPlane(cam, tileSpan(tx, ty, frame.image.x, frame.image.y), planes);
}

// For each tile: 1 where a camera ray may meet the extent's boxes. From the start distances
// where the caller has them: the start blocks hold the same surfaces, in finer blocks, and a
// tile's start is finite exactly where one of them may be met (no second projection of boxes).
std::vector<uint8_t> tilesSeeingExtent(const gpu::GpuFrameParams &frame, const RayFrame &cam,
                                       const SceneExtent &extent,
                                       const std::vector<float> *starts) {
    if (!starts)
        return tilesSeeingBoxes(frame, cam, extent.boxes);
    std::vector<uint8_t> seen(starts->size());
    for (size_t i = 0; i < seen.size(); ++i)
        seen[i] = (*starts)[i] < kNoBoxAhead ? 1 : 0;
    return seen;
}

} // namespace

std::vector<uint8_t> tilesThatMayHit(const gpu::GpuFrameParams &frame, const SceneExtent &extent,
                                     const std::vector<float> *starts) {
    RayFrame cam = rayFrame(frame);
    std::vector<uint8_t> mayHit = tilesSeeingExtent(frame, cam, extent, starts);
    uint32_t tilesX = imageTiles(frame.image.x, frame.image.y).x1;
    for (size_t i = 0; i < mayHit.size(); ++i)
        mayHit[i] = mayHit[i] || tileSeesAPlane(frame, cam, extent.planes, uint32_t(i % tilesX),
                                                uint32_t(i / tilesX));
    return mayHit;
}

std::vector<uint8_t> tileClasses(const gpu::GpuFrameParams &frame, const SceneExtent &extent,
                                 const std::vector<Aabb> &planeShadows,
                                 const std::vector<float> *starts) {
    RayFrame cam = rayFrame(frame);
    std::vector<uint8_t> classes = tilesSeeingExtent(frame, cam, extent, starts);
    std::vector<uint8_t> shadowed = tilesSeeingBoxes(frame, cam, planeShadows);
    uint32_t tilesX = imageTiles(frame.image.x, frame.image.y).x1;
    for (size_t i = 0; i < classes.size(); ++i) {
        if (classes[i]) {
            classes[i] = kTileFull;
        } else if (tileSeesAPlane(frame, cam, extent.planes, uint32_t(i % tilesX),
                                  uint32_t(i / tilesX))) {
            classes[i] = shadowed[i] ? kTileFull : kTilePlanesOnly;
        } else {
            classes[i] = kTileBackground;
        }
    }
    return classes;
}

std::vector<float> tileStartDistances(const gpu::GpuFrameParams &frame,
                                      const std::vector<Aabb> &boxes) {
    RayFrame cam = rayFrame(frame);
    TileRect image = imageTiles(frame.image.x, frame.image.y);
    size_t tiles = size_t(image.width()) * image.height();
    // Tens of thousands of boxes a frame, on the host while the device waits: split over the
    // cores, each part its own distances, then the least of them (the same in any order).
    constexpr size_t kBoxesPerPart = 4096;
    size_t parts = std::clamp<size_t>(boxes.size() / kBoxesPerPart, 1, parallelThreadCount());
    std::vector<std::vector<float>> partStarts(parts, std::vector<float>(tiles, kNoBoxAhead));
    parallelFor(parts, [&](size_t part) {
        std::vector<float> &starts = partStarts[part];
        size_t first = boxes.size() * part / parts, last = boxes.size() * (part + 1) / parts;
        forEachSeenBox(frame, cam, boxes, first, last, [&](const TileRect &t, bool, float start) {
            auto lower = [&](uint32_t x, uint32_t y) {
                float &tile = starts[size_t(y) * image.x1 + x];
                tile = std::min(tile, start);
            };
            if (t.x1 - t.x0 <= 2 && t.y1 - t.y0 <= 2) {
                // Most blocks: without branches, the first and last tile of each axis (the
                // same tile where there is one; lowering a tile twice changes nothing).
                lower(t.x0, t.y0), lower(t.x1 - 1, t.y0);
                lower(t.x0, t.y1 - 1), lower(t.x1 - 1, t.y1 - 1);
                return true;
            }
            for (uint32_t y = t.y0; y < t.y1; ++y)
                for (uint32_t x = t.x0; x < t.x1; ++x)
                    lower(x, y);
            return true;
        });
    });
    for (size_t part = 1; part < parts; ++part)
        for (size_t i = 0; i < tiles; ++i)
            partStarts[0][i] = std::min(partStarts[0][i], partStarts[part][i]);
    return std::move(partStarts[0]);
}

std::vector<uint32_t> spreadRowOrder(uint32_t rows, uint32_t shares) {
    if (shares > 0) {
        std::vector<uint32_t> order;
        order.reserve(rows);
        for (uint32_t s = 0; s < shares; ++s)
            for (uint32_t r = s; r < rows; r += shares)
                order.push_back(r);
        return order;
    }
    uint32_t bits = 0;
    while ((1u << bits) < rows)
        ++bits;
    std::vector<uint32_t> order;
    order.reserve(rows);
    for (uint32_t i = 0; i < (1u << bits); ++i) {
        uint32_t reversed = 0;
        for (uint32_t b = 0; b < bits; ++b)
            reversed |= ((i >> b) & 1u) << (bits - 1 - b);
        if (reversed < rows)
            order.push_back(reversed);
    }
    return order;
}

TileLists tileLists(const std::vector<uint8_t> &classes, const TileRect &image,
                    const std::vector<float> &starts, uint32_t shares, const TileRect &window) {
    const TileRect &w = window.empty() ? image : window;
    TileLists lists;
    lists.tiles.reserve(size_t(w.width()) * w.height());
    lists.starts.reserve(size_t(w.width()) * w.height());
    std::vector<uint32_t> rows = spreadRowOrder(w.height(), shares);
    std::array<uint32_t, 3> counts{};
    for (uint8_t wanted : {kTileFull, kTilePlanesOnly, kTileBackground})
        for (uint32_t row : rows)
            for (uint32_t tx = w.x0; tx < w.x1; ++tx) {
                uint32_t ty = w.y0 + row;
                size_t i = size_t(ty) * image.x1 + tx;
                if (classes[i] == wanted) {
                    lists.tiles.push_back(packTile(tx, ty));
                    lists.starts.push_back(starts.empty() ? 0.0f : starts[i]);
                    counts[wanted] += 1;
                }
            }
    lists.full = counts[kTileFull];
    lists.traced = lists.full + counts[kTilePlanesOnly];
    return lists;
}

TileLists allTiles(const TileRect &image, const TileRect &window) {
    return tileLists(std::vector<uint8_t>(size_t(image.width()) * image.height(), kTileFull), image,
                     {}, 0, window);
}

} // namespace prism
