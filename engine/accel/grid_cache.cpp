#include "accel/grid_cache.h"

#include <algorithm>
#include <filesystem>

#include "accel/grid_source_digest.h"
#include "cache/blob.h"
#include "cache/content_hash.h"
#include "cache/disk_cache.h"
#include "core/timer.h"

namespace prism {
namespace {

// Positions of many triangles, digested in blocks: one call per triangle would cost more
// than the digest itself.
void addTrianglePositions(ContentHash &hash, const std::vector<Triangle> &triangles) {
    hash.value(uint64_t(triangles.size()));
    constexpr size_t kBlock = 4096;
    std::vector<glm::dvec3> block;
    block.reserve(3 * kBlock);
    for (size_t first = 0; first < triangles.size(); first += kBlock) {
        block.clear();
        size_t last = std::min(triangles.size(), first + kBlock);
        for (size_t i = first; i < last; ++i)
            block.insert(block.end(), triangles[i].p, triangles[i].p + 3);
        hash.bytes(block.data(), block.size() * sizeof(glm::dvec3));
    }
}

void packInto(BlobWriter &out, const Grid &g) {
    out.value(g.boundsMin);
    out.value(g.boundsMax);
    out.value(g.resolution);
    out.value(g.cellSize);
    out.values(g.cellStart);
    out.values(g.cellPrimitives);
    out.value(g.shift);
    out.values(g.entries);
    out.values(g.cellBoxes);
    out.value(g.depth);
    out.value(uint8_t(g.lean));
    out.value(g.maxPerCell);
    out.text(g.choice);
    out.value(uint64_t(g.meshGrids.size()));
    for (const Grid &mesh : g.meshGrids)
        packInto(out, mesh);
}

Grid unpackFrom(BlobReader &in, int level) {
    if (level > 1) // a scene's grid, and one regular grid per prototype below it
        throw BlobFormatError("grids nested deeper than a prototype's");
    Grid g;
    g.boundsMin = in.value<glm::vec3>();
    g.boundsMax = in.value<glm::vec3>();
    g.resolution = in.value<glm::ivec3>();
    g.cellSize = in.value<glm::vec3>();
    g.cellStart = in.values<uint32_t>();
    g.cellPrimitives = in.values<uint32_t>();
    g.shift = in.value<uint32_t>();
    g.entries = in.values<uint32_t>();
    g.cellBoxes = in.values<glm::uvec4>();
    g.depth = in.value<uint32_t>();
    g.lean = in.value<uint8_t>() != 0;
    g.maxPerCell = in.value<uint32_t>();
    g.choice = in.text();
    uint64_t meshes = in.value<uint64_t>();
    for (uint64_t m = 0; m < meshes; ++m)
        g.meshGrids.push_back(unpackFrom(in, level + 1));
    // What the tracer indexes with must hang together; the checksum makes a damaged entry
    // unlikely to get here, but a wrong grid would render wrong, not fail.
    if (g.cellStart.empty() && g.cellPrimitives.size() > 0)
        throw BlobFormatError("cell lists without their starts");
    if (!g.cellStart.empty() && g.cellStart.back() != g.cellPrimitives.size())
        throw BlobFormatError("cell starts do not end at the list's end");
    return g;
}

} // namespace

std::string gridCacheKey(const Scene &scene, const GridOptions &options) {
    return gridCacheKey(scene, options, meshGridsKey(scene));
}

std::string gridCacheKey(const Scene &scene, const GridOptions &options,
                         const std::string &meshKey) {
    ContentHash hash;
    hash.text("prism grid").text(PRISM_GRID_SOURCE_DIGEST).value(kGridCacheFormat);
    hash.value(int32_t(options.mode)).value(options.resolution).value(options.density);
    // The effort as decided, not the samples it was decided by: every image size that decides
    // alike shares the entry.
    hash.value(uint8_t(buildsLean(options, scene.finitePrimitiveCount())));
    hash.value(uint64_t(scene.spheres.size()));
    for (const Sphere &s : scene.spheres)
        hash.value(s.center).value(s.radius);
    addTrianglePositions(hash, scene.triangles);
    hash.text(meshKey); // the prototypes' positions, digested once (meshGridsKey)
    hash.value(uint64_t(scene.instances.size()));
    for (const Instance &i : scene.instances)
        hash.value(i.prototype).value(i.scale).value(i.rotation).value(i.translation);
    // The choice traces camera rays against the primitives, planes included.
    hash.value(uint64_t(scene.planes.size()));
    for (const Plane &p : scene.planes)
        hash.value(p.point).value(p.normal);
    if (options.mode == GridOptions::Mode::Auto) {
        const Camera &c = scene.camera;
        hash.value(c.eye).value(c.look).value(c.up).value(c.fovDegrees).value(c.orthoHeight);
    }
    return hash.hex();
}

std::string meshGridsKey(const Scene &scene) {
    if (scene.prototypes.empty())
        return {};
    ContentHash hash;
    hash.text("prism mesh grids").text(PRISM_GRID_SOURCE_DIGEST).value(kGridCacheFormat);
    hash.value(uint64_t(scene.prototypes.size()));
    for (const MeshPrototype &prototype : scene.prototypes)
        addTrianglePositions(hash, prototype.triangles);
    return hash.hex();
}

namespace {

// The grid's entry, its arrays borrowed from it.
BlobWriter gridRecord(const Grid &grid) {
    BlobWriter out;
    packInto(out, grid);
    return out;
}

} // namespace

std::string packGrid(const Grid &grid) {
    return gridRecord(grid).take();
}

Grid unpackGrid(std::string_view bytes) {
    BlobReader in(bytes);
    Grid grid = unpackFrom(in, 0);
    if (!in.atEnd())
        throw BlobFormatError("bytes left over after the grid");
    return grid;
}

Grid buildGridCached(const Scene &scene, const GridOptions &options, const GridCachePolicy &policy,
                     GridCacheOutcome *outcome) {
    GridCacheOutcome local;
    GridCacheOutcome &o = outcome ? *outcome : local;
    if (!policy.cache) {
        o.state = "off";
        return buildGrid(scene, options);
    }
    Timer timer;
    o.key = policy.key.empty() ? gridCacheKey(scene, options) : policy.key;
    o.keyMs = timer.elapsedMs();
    timer.reset();
    if (std::optional<CacheEntry> entry = policy.cache->load("grid", o.key, kGridCacheFormat)) {
        try {
            Grid grid = unpackGrid(entry->payload);
            o.readMs = timer.elapsedMs();
            o.state = "hit";
            return grid;
        } catch (const BlobFormatError &e) {
            policy.cache->discard("grid", o.key, e.what());
        }
    }
    Grid grid = buildGrid(scene, options);
    timer.reset();
    policy.cache->store("grid", o.key, kGridCacheFormat, gridRecord(grid).pieces());
    o.storeMs = timer.elapsedMs();
    o.state = "miss";
    return grid;
}

} // namespace prism
