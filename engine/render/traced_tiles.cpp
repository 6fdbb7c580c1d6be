#include "render/traced_tiles.h"

#include <algorithm>
#include <array>
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
    glm::dmat3 toImage; // p - eye -> (a, b, c) with p - eye = a du + b dv + c forward
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

// `box` grown by a relative margin, so that rounding in the host's own arithmetic cannot cut it.
Aabb padded(const Aabb &box) {
    glm::dvec3 pad =
        kEpsilon * (glm::abs(box.max - box.min) + glm::abs(box.min) + glm::abs(box.max)) + 1e-30;
    Aabb grown;
    grown.min = box.min - pad;
    grown.max = box.max + pad;
    return grown;
}

// Corner k (0-7: bit 0 x, bit 1 y, bit 2 z high) of `box`.
glm::dvec3 corner(const Aabb &box, int k) {
    return {(k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
            (k & 4) ? box.max.z : box.min.z};
}

// Where a box can be seen: the rectangle of image-plane coordinates its rays pass through.
// Perspective rays leave the eye along forward + x du + y dv, so a point at (a, b, c) is seen at
// (a / c, b / c) when c > 0, and the rays through a box in front of the eye cross the image
// plane inside the hull of its corners' images. Parallel rays leave (x, y) along forward: a
// point is seen at (a, b) when c > 0. Returns false when the box is behind the camera; `all` is
// set when it reaches back to the eye's plane (then any ray may meet it).
struct ImageRect {
    double x0, x1, y0, y1;
};
bool boxImage(const RayFrame &cam, const Aabb &box, ImageRect &rect, bool &all) {
    Aabb grown = padded(box);
    rect = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    all = false;
    bool inFront = false, reachesBack = false;
    // The corners' (a, b, c) from the lowest corner's and the box's edges along the camera's
    // axes: three products instead of eight (tens of thousands of boxes a frame; the results
    // differ from the direct products in the last bits, far inside the padding).
    glm::dvec3 base = cam.toImage * (grown.min - cam.eye);
    glm::dvec3 size = grown.max - grown.min;
    glm::dvec3 edge[3] = {cam.toImage[0] * size.x, cam.toImage[1] * size.y,
                          cam.toImage[2] * size.z};
    for (int k = 0; k < 8; ++k) {
        glm::dvec3 abc = base;
        for (int a = 0; a < 3; ++a)
            if (k & (1 << a))
                abc += edge[a];
        inFront = inFront || abc.z > 0.0;
        if (cam.parallel) {
            rect = {std::min(rect.x0, abc.x), std::max(rect.x1, abc.x), std::min(rect.y0, abc.y),
                    std::max(rect.y1, abc.y)};
            continue;
        }
        // A corner near or behind the eye's plane would project far off or flipped.
        if (abc.z <= kEpsilon * (std::abs(abc.x) + std::abs(abc.y) + std::abs(abc.z))) {
            reachesBack = true;
            continue;
        }
        double inverse = 1.0 / abc.z, x = abc.x * inverse, y = abc.y * inverse;
        rect = {std::min(rect.x0, x), std::max(rect.x1, x), std::min(rect.y0, y),
                std::max(rect.y1, y)};
    }
    all = inFront && reachesBack;
    return inFront;
}

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
    std::vector<uint8_t> occupied(size_t(res.x) * res.y * res.z, 0);
    for (uint32_t id = 0; id < primitives.count(); ++id) {
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
                 glm::dvec3(frame.dv),  gpu::isParallelCamera(frame), glm::dmat3(1.0)};
    cam.toImage = glm::inverse(glm::dmat3(cam.du, cam.dv, cam.forward));
    return cam;
}

// The tiles whose camera rays may pass through `box`: false when none may; `all` when every
// one may (the box reaches back to the eye's plane).
bool boxTiles(const gpu::GpuFrameParams &frame, const RayFrame &cam, const Aabb &box,
              TileRect &tiles, bool &all) {
    uint32_t width = frame.image.x, height = frame.image.y;
    TileRect image = imageTiles(width, height);
    ImageRect r;
    if (!boxImage(cam, box, r, all))
        return false;
    if (all) {
        tiles = image;
        return true;
    }
    // Pixels whose sample positions may fall in the rectangle, one more each side (the tile
    // span's margin), then their tiles.
    double px0 = (r.x0 + 1.0) * 0.5 * width - 1.0, px1 = (r.x1 + 1.0) * 0.5 * width + 1.0;
    double py0 = (1.0 - r.y1) * 0.5 * height - 1.0, py1 = (1.0 - r.y0) * 0.5 * height + 1.0;
    if (px1 < 0.0 || py1 < 0.0 || px0 >= width || py0 >= height)
        return false;
    tiles.x0 = uint32_t(std::max(0.0, px0)) / kTileSize;
    tiles.y0 = uint32_t(std::max(0.0, py0)) / kTileSize;
    tiles.x1 = std::min(image.x1, uint32_t(std::min(double(width), px1)) / kTileSize + 1);
    tiles.y1 = std::min(image.y1, uint32_t(std::min(double(height), py1)) / kTileSize + 1);
    return true;
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
    for (const Aabb &box : boxes) {
        TileRect t;
        bool all;
        if (!boxTiles(frame, cam, box, t, all))
            continue;
        if (all)
            return std::vector<uint8_t>(size_t(tilesX) * tilesY, 1);
        at(t.x0, t.y0) += 1;
        at(t.x1, t.y0) -= 1;
        at(t.x0, t.y1) -= 1;
        at(t.x1, t.y1) += 1;
    }
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

// A distance t below which no camera ray o + t d of the frame meets the box. Perspective rays
// leave the eye with unit directions, so t is the distance from the eye, at least the box's.
// Parallel rays leave the image plane along forward: t is a point's depth beyond that plane,
// less what du and dv add to it for a camera whose axes are not quite square. With a relative
// margin far above the shader's rounding (a few 1e-7 of t), and never below 0.
double distanceBeforeBox(const RayFrame &cam, const Aabb &box) {
    Aabb grown = padded(box);
    double t;
    if (cam.parallel) {
        double ff = glm::dot(cam.forward, cam.forward);
        t = INFINITY;
        for (int k = 0; k < 8; ++k)
            t = std::min(t, glm::dot(corner(grown, k) - cam.eye, cam.forward) / ff);
        // Samples lie within a pixel of the image: |x|, |y| < 1.1 for any image of 20 pixels.
        t -= 1.1 *
             (std::abs(glm::dot(cam.du, cam.forward)) + std::abs(glm::dot(cam.dv, cam.forward))) /
             ff;
    } else {
        t = glm::length(
            glm::max(glm::max(grown.min - cam.eye, cam.eye - grown.max), glm::dvec3(0.0)));
    }
    return std::max(0.0, t * (1.0 - 1e-4));
}

bool tileSeesAPlane(const gpu::GpuFrameParams &frame, const RayFrame &cam,
                    const std::vector<glm::dvec4> &planes, uint32_t tx, uint32_t ty) {
    return !planes.empty() &&
           tileMayHitAPlane(cam, tileSpan(tx, ty, frame.image.x, frame.image.y), planes);
}

} // namespace

std::vector<uint8_t> tilesThatMayHit(const gpu::GpuFrameParams &frame, const SceneExtent &extent) {
    RayFrame cam = rayFrame(frame);
    std::vector<uint8_t> mayHit = tilesSeeingBoxes(frame, cam, extent.boxes);
    uint32_t tilesX = imageTiles(frame.image.x, frame.image.y).x1;
    for (size_t i = 0; i < mayHit.size(); ++i)
        mayHit[i] = mayHit[i] || tileSeesAPlane(frame, cam, extent.planes, uint32_t(i % tilesX),
                                                uint32_t(i / tilesX));
    return mayHit;
}

std::vector<uint8_t> tileClasses(const gpu::GpuFrameParams &frame, const SceneExtent &extent,
                                 const std::vector<Aabb> &planeShadows) {
    RayFrame cam = rayFrame(frame);
    std::vector<uint8_t> classes = tilesSeeingBoxes(frame, cam, extent.boxes);
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
        for (size_t b = first; b < last; ++b) {
            const Aabb &box = boxes[b];
            TileRect t;
            bool all;
            if (!boxTiles(frame, cam, box, t, all))
                continue;
            // Rounded down to a float: the shader's t is one.
            double d = distanceBeforeBox(cam, box);
            float start = float(d);
            if (double(start) > d)
                start = std::nextafter(start, 0.0f);
            for (uint32_t y = t.y0; y < t.y1; ++y)
                for (uint32_t x = t.x0; x < t.x1; ++x) {
                    float &tile = starts[size_t(y) * image.x1 + x];
                    tile = std::min(tile, start);
                }
        }
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
    return tileLists(std::vector<uint8_t>(size_t(image.width()) * image.height(), kTileFull),
                     image, {}, 0, window);
}

} // namespace prism
