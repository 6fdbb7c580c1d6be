#include "render/scene_packing.h"

#include <algorithm>
#include <bit>
#include <string>

#include "core/error.h"
#include "core/parallel_for.h"
#include "scene/primitive_ids.h"

namespace prism {
namespace {

// Material and prototype indices travel in float lanes (gpu::indexFromFloat); floats hold
// integers exactly below 2^24.
float indexAsFloat(uint32_t index, const char *what = "materials") {
    if (index >= (1u << 24))
        throw Error(std::string("scene has more than 16,777,216 ") + what);
    return static_cast<float>(index);
}

// Row r of the 3x4 matrix p -> offset + linear * p.
glm::vec4 affineRow(const glm::dmat3 &linear, const glm::dvec3 &offset, int r) {
    return glm::vec4(float(linear[0][r]), float(linear[1][r]), float(linear[2][r]),
                     float(offset[r]));
}

// The placements, and each prototype's grid after the scene grid in the cell arrays, listing
// triangles by their place in the triangle array (firstTriangle[1 + prototype] onwards).
void packInstances(const Scene &scene, const Grid &grid, const std::vector<uint32_t> &firstTriangle,
                   PackedScene &packed) {
    if (grid.meshGrids.size() != scene.prototypes.size())
        throw Error("the grid has " + std::to_string(grid.meshGrids.size()) + " mesh grids for " +
                    std::to_string(scene.prototypes.size()) + " prototypes");
    if (!grid.meshGrids.empty()) { // the scene grid's arrays, then each prototype's
        packed.ownedCellStart = grid.cellStart;
        packed.ownedCellPrimitives = grid.cellPrimitives;
    }
    std::vector<uint32_t> &cellStart = packed.ownedCellStart;
    std::vector<uint32_t> &cellPrimitives = packed.ownedCellPrimitives;
    for (size_t m = 0; m < grid.meshGrids.size(); ++m) {
        const Grid &g = grid.meshGrids[m];
        uint64_t firstCell = cellStart.size();
        uint64_t firstEntry = cellPrimitives.size();
        if (firstCell + g.cellStart.size() >= (uint64_t(1) << 32) ||
            firstEntry + g.cellPrimitives.size() >= (uint64_t(1) << 32))
            throw Error("the prototypes' grids hold more than 2^32 cells or entries");
        for (uint32_t start : g.cellStart)
            cellStart.push_back(uint32_t(firstEntry) + start);
        for (uint32_t local : g.cellPrimitives)
            cellPrimitives.push_back(firstTriangle[1 + m] + local);
        glm::uvec3 res(g.resolution);
        packed.meshGrids.push_back({glm::vec4(g.boundsMin, 0.0f), glm::vec4(g.boundsMax, 0.0f),
                                    glm::vec4(g.cellSize, 0.0f),
                                    glm::uvec4(res, uint32_t(firstCell))});
    }
    for (const Instance &i : scene.instances) {
        glm::dmat3 toObject = glm::transpose(i.rotation) / i.scale;
        glm::dvec3 toObjectOffset = -(toObject * i.translation);
        glm::dmat3 toWorld = i.scale * i.rotation;
        float material = i.material == kOwnMaterials ? -1.0f : indexAsFloat(uint32_t(i.material));
        packed.instances.push_back(
            {affineRow(toObject, toObjectOffset, 0), affineRow(toObject, toObjectOffset, 1),
             affineRow(toObject, toObjectOffset, 2), affineRow(toWorld, i.translation, 0),
             affineRow(toWorld, i.translation, 1), affineRow(toWorld, i.translation, 2),
             glm::vec4(indexAsFloat(i.prototype, "prototypes"), material, 0.0f, 0.0f)});
    }
    if (!grid.meshGrids.empty()) {
        packed.cellStart = cellStart;
        packed.cellPrimitives = cellPrimitives;
    }
}

// Each cell entry's sphere, in list order. A scene with spheres only numbers them from 0.
void packCellSpheres(const Scene &scene, PackedScene &packed) {
    if (!scene.triangles.empty() || !scene.instances.empty())
        throw Error("cell spheres need a scene whose grid holds spheres only");
    packed.cellSpheres.reserve(packed.cellPrimitives.size());
    for (uint32_t id : packed.cellPrimitives)
        packed.cellSpheres.push_back(packed.spheres.at(id).centerRadius);
}

} // namespace

PackedScene packScene(const Scene &scene, const Grid &grid, bool cellTriangles, bool cellSpheres) {
    PackedScene packed;
    gpu::GpuSceneHeader &h = packed.header;
    h.gridMin = glm::vec4(grid.boundsMin, 0.0f);
    h.gridMax = glm::vec4(grid.boundsMax, 0.0f);
    h.cellSize = glm::vec4(grid.cellSize, 0.0f);
    glm::uvec3 res(grid.resolution);
    h.gridRes = glm::uvec4(res, res.x * res.y * res.z);
    h.counts = glm::uvec4(scene.spheres.size(), scene.planes.size(), scene.triangles.size(),
                          scene.lights.size());
    h.idEnd = PrimitiveIds(scene).end;
    h.background = glm::vec4(scene.background, 1.0f);
    h.ambient = glm::vec4(scene.ambient, 1.0f);
    const Environment &e = scene.environment;
    h.environment = glm::vec4(float(e.texture), e.intensity, glm::radians(e.rotateDegrees), 0.0f);

    for (const Sphere &s : scene.spheres)
        packed.spheres.push_back(
            {glm::vec4(s.center, s.radius), glm::vec4(indexAsFloat(s.material), 0.0f, 0.0f, 0.0f)});
    for (const Plane &p : scene.planes)
        packed.planes.push_back(
            {glm::vec4(p.normal, float(glm::dot(glm::dvec3(p.normal), p.point))),
             glm::vec4(glm::vec3(p.point), indexAsFloat(p.material))});

    // The tracer reads shading data for every triangle hit where the scene has vertex normals,
    // textures or normal/bump maps (tracer_features.h): then every triangle has its record.
    packed.triangleLists.push_back({scene.triangles, scene.triangleShading});
    for (const MeshPrototype &m : scene.prototypes)
        packed.triangleLists.push_back({m.triangles, m.shading});
    bool needShading = false, anyTriangles = false;
    std::vector<uint32_t> firstTriangle; // of each list
    for (const PackedScene::TriangleList &list : packed.triangleLists) {
        firstTriangle.push_back(uint32_t(packed.triangleCount));
        packed.triangleCount += list.triangles.size();
        anyTriangles = anyTriangles || !list.triangles.empty();
        for (const Triangle &t : list.triangles)
            (void)indexAsFloat(t.material); // checked here, written as a float lane later
        for (const TriangleShading &s : list.shading)
            needShading = needShading || s.hasNormals || s.hasUVs;
    }
    for (const Material &m : scene.materials)
        needShading =
            needShading || ((m.texture != kNoTexture || m.hasSurfaceMaps()) && anyTriangles);
    packed.triangleShading = needShading;
    if (packed.triangleCount >= (uint64_t(1) << 29))
        throw Error("scene has more than 2^29 triangles, prototypes' included"); // resume.glsl

    for (const Material &m : scene.materials)
        packed.materials.push_back(
            {glm::vec4(m.color, m.ambient),
             glm::vec4(m.diffuse, m.specular, m.shininess, m.reflect),
             glm::vec4(m.transmit, m.ior, static_cast<float>(m.texture), 0.0f),
             glm::vec4(static_cast<float>(m.normalMap), static_cast<float>(m.bumpMap), m.bumpScale,
                       0.0f)});
    for (const Light &l : scene.lights)
        packed.lights.push_back({glm::vec4(l.position, l.radius), glm::vec4(l.color, 1.0f)});

    for (const Texture &t : scene.textures) {
        packed.textures.push_back({glm::uvec4(packed.texels.size(), t.width, t.height, 0)});
        packed.texels.insert(packed.texels.end(), t.texels.begin(), t.texels.end());
    }

    packed.cellStart = grid.cellStart; // views; packInstances appends the prototypes' grids
    packed.cellPrimitives = grid.cellPrimitives;
    // The cell triangles are written at upload (writeCellTriangles). The grid's ids are
    // triangle indices here: a scene with triangles only numbers them from 0
    // (scene/primitive_ids.h), and those are the first entries of packed.triangles.
    if (cellTriangles && (!scene.spheres.empty() || !scene.instances.empty()))
        throw Error("cell triangles need a scene whose grid holds triangles only");
    packed.cellTriangles = cellTriangles;
    if (cellSpheres)
        packCellSpheres(scene, packed);
    packInstances(scene, grid, firstTriangle, packed);
    packed.gridEntries = grid.entries;
    packed.cellBoxes = grid.cellBoxes; // w added by writeCellBoxes
    if (cellTriangles && grid.adaptive()) {
        // The leaves name their cell's record (gpu::cellRecordRow), whose rows must fit the
        // entries' 28 bits; chooseFeatures keeps grids that do not off cell triangles.
        if (cellTriangleRows(grid, true) > kMaxAdaptiveIndex)
            throw Error("adaptive grid's cell records need more than 2^28 rows");
        packed.cellRecords = true;
        packed.ownedGridEntries = grid.entries;
        for (uint32_t &entry : packed.ownedGridEntries)
            if (gpu::entrySplit(entry) == 0) {
                uint32_t cell = gpu::entryTarget(entry);
                entry = gpu::cellRecordRow(cell, grid.cellStart[cell]) << 4;
            }
        packed.gridEntries = packed.ownedGridEntries;
    }
    h.voxelSize = glm::vec4(grid.voxelSize(), 0.0f);
    h.voxels = glm::uvec4(glm::uvec3(grid.voxelResolution()), grid.shift);
    return packed;
}

uint64_t cellTriangleRows(const Grid &grid, bool cellTriangles) {
    if (!cellTriangles)
        return 0;
    return 3 * uint64_t(grid.cellPrimitives.size()) + (grid.adaptive() ? grid.cellCount() : 0);
}

uint64_t cellTriangleRows(const PackedScene &packed) {
    if (!packed.cellTriangles)
        return 0;
    return 3 * uint64_t(packed.cellPrimitives.size()) +
           (packed.cellRecords ? packed.cellBoxes.size() : 0);
}

namespace {

gpu::GpuTriangle toGpu(const Triangle &t, std::span<const TriangleShading>) {
    return {glm::vec4(t.p[0], float(t.material)), glm::vec4(t.p[1], 0.0f), glm::vec4(t.p[2], 0.0f)};
}

gpu::GpuTriangleShading toGpuShading(const Triangle &t, std::span<const TriangleShading> list) {
    const TriangleShading &s = shadingOf(t, list);
    return {glm::vec4(s.n[0], s.hasNormals ? 1.0f : 0.0f),
            glm::vec4(s.n[1], s.hasUVs ? 1.0f : 0.0f), glm::vec4(s.n[2], 0.0f),
            glm::vec4(s.uv[0], s.uv[1]), glm::vec4(s.uv[2], 0.0f, 0.0f)};
}

// Each list's records into `out` in order, by blocks on every core: a 1M-triangle array is the
// device's fresh memory, faulted in as it is first written.
template <typename Record, typename Convert>
void writeRecords(const PackedScene &packed, std::span<Record> out, Convert convert,
                  const char *what) {
    if (out.size() != packed.triangleCount)
        throw Error(std::string(what) + " array of " + std::to_string(out.size()) +
                    " records, not " + std::to_string(packed.triangleCount));
    size_t first = 0;
    for (const PackedScene::TriangleList &list : packed.triangleLists) {
        parallelForInBlocks(list.triangles.size(), 1 << 15, [&](size_t i) {
            out[first + i] = convert(list.triangles[i], list.shading);
        });
        first += list.triangles.size();
    }
}

// Cell entry k's triangle as three rows from `rows` on (gpu::GpuCellTriangle).
void writeTriangleRows(const PackedScene &packed, size_t k, glm::uvec4 *rows) {
    uint32_t id = packed.cellPrimitives[k];
    gpu::GpuTriangle t = packedTriangle(packed, id);
    rows[0] = glm::floatBitsToUint(glm::vec4(glm::vec3(t.v0), 0.0f));
    rows[0].w = id;
    rows[1] = glm::floatBitsToUint(glm::vec4(glm::vec3(t.v1), 0.0f));
    rows[2] = glm::floatBitsToUint(glm::vec4(glm::vec3(t.v2), 0.0f));
}

} // namespace

gpu::GpuTriangle packedTriangle(const PackedScene &packed, uint64_t i) {
    for (const PackedScene::TriangleList &list : packed.triangleLists) {
        if (i < list.triangles.size())
            return toGpu(list.triangles[i], list.shading);
        i -= list.triangles.size();
    }
    throw Error("packed triangle past the " + std::to_string(packed.triangleCount) + " there are");
}

void writeTriangles(const PackedScene &packed, std::span<gpu::GpuTriangle> out) {
    writeRecords(packed, out, toGpu, "triangle");
}

void writeTriangleShading(const PackedScene &packed, std::span<gpu::GpuTriangleShading> out) {
    if (!packed.triangleShading && !out.empty())
        throw Error("triangle shading array written for a scene that needs none");
    if (packed.triangleShading)
        writeRecords(packed, out, toGpuShading, "triangle shading");
}

void writeCellBoxes(const PackedScene &packed, std::span<glm::uvec4> out) {
    if (out.size() != packed.cellBoxes.size())
        throw Error("cell box array of " + std::to_string(out.size()) + " rows, not " +
                    std::to_string(packed.cellBoxes.size()));
    // In parallel, as the cell triangles below: the device's fresh memory faults in as it is
    // first written.
    parallelForInBlocks(out.size(), 1 << 16, [&](size_t c) {
        out[c] = packed.cellBoxes[c];
        out[c].w = packed.cellStart[c]; // gpu::cellBoxFirstPrimitive
    });
}

void writeCellTriangles(const PackedScene &packed, std::span<glm::uvec4> out) {
    if (out.size() != cellTriangleRows(packed))
        throw Error("cell triangle array of " + std::to_string(out.size()) + " rows, not " +
                    std::to_string(cellTriangleRows(packed)));
    // In parallel, each block its own rows: the 1M-triangle scene has 5.3M entries, and the
    // device's fresh memory faults in page by page as it is first written.
    constexpr size_t kBlock = 1 << 16;
    if (!packed.cellRecords) {
        parallelForInBlocks(packed.cellPrimitives.size(), kBlock,
                            [&](size_t k) { writeTriangleRows(packed, k, &out[3 * k]); });
        return;
    }
    parallelForInBlocks(packed.cellBoxes.size(), kBlock, [&](size_t c) {
        uint32_t first = packed.cellStart[c], end = packed.cellStart[c + 1];
        size_t row = gpu::cellRecordRow(uint32_t(c), first);
        out[row] = packed.cellBoxes[c];
        out[row].w = end - first; // gpu::cellRecordCount
        for (uint32_t k = first; k < end; ++k)
            writeTriangleRows(packed, k,
                              &out[gpu::cellRecordTriangleRow(uint32_t(row), k - first)]);
    });
}

} // namespace prism
