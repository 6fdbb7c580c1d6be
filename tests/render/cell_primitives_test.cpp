// Cell primitives: in a scene whose grid lists triangles only (spheres only), each cell entry's
// triangle (sphere) is stored in list order so that a test needs no primitive id. The packed
// entries must be the listed primitives, exactly; the variants must be chosen only where they
// apply and fit; and they must change no pixel, AOV or ray count on either grid, resumed or not.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "accel/grid.h"
#include "core/error.h"
#include "gpu_fixture.h"
#include "render/resume_plan.h"
#include "render/scene_packing.h"
#include "render/tracer_features.h"
#include "render_helpers.h"
#include "scene_builders.h"
#include "test_scenes.h"

namespace prism::test {
namespace {

// A floor, and flat and smooth octahedra (vertex normals: shading reads the hit triangle's own
// record, so a wrong triangle index shows) that reflect, refract and cast shadows.
Scene triangleScene() {
    Scene scene = sceneWithDefaultMaterial();
    uint32_t floor = addMaterial(scene, "floor", {0.7f, 0.7f, 0.7f}, 0.2f);
    uint32_t mirror = addMaterial(scene, "mirror", {0.9f, 0.9f, 0.9f}, 0.8f);
    uint32_t glass = addMaterial(scene, opticalMaterial("glass", 0.1f, 0.85f, 1.5f));
    uint32_t red = addMaterial(scene, "red", {0.9f, 0.2f, 0.1f});
    uint32_t blue = addMaterial(scene, "blue", {0.2f, 0.3f, 0.9f});
    scene.camera.eye = {0.0f, 2.5f, 7.0f};
    scene.camera.look = {0.0f, 0.8f, 0.0f};
    scene.camera.fovDegrees = 50.0f;
    scene.background = {0.1f, 0.1f, 0.15f};
    scene.lights.push_back(Light{{4.0f, 6.0f, 5.0f}, {1.0f, 1.0f, 1.0f}, 0.3f});
    scene.planes.push_back(Plane{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, floor});
    addOctahedron(scene, {-1.6f, 1.0f, 0.0f}, 1.0f, mirror);
    addSmoothOctahedron(scene, {0.9f, 0.7f, 1.2f}, 0.7f, glass);
    addSmoothOctahedron(scene, {1.8f, 0.5f, -1.0f}, 0.5f, red);
    addOctahedron(scene, {0.2f, 0.6f, -1.6f}, 0.6f, blue);
    return scene;
}

// The stability scene without its octahedron: spheres (mirror, glass, diffuse) on a floor.
Scene sphereScene() {
    Scene scene = stabilityScene();
    scene.triangles.clear();
    return scene;
}

// Expects rows[row..row + 2] to be cell entry k's triangle (gpu::GpuCellTriangle).
void expectCellTriangle(const Scene &scene, const Grid &grid, const PackedScene &packed,
                        const std::vector<glm::uvec4> &rows, size_t row, size_t k) {
    ASSERT_LE(row + 3, rows.size());
    uint32_t id = grid.cellPrimitives[k];
    ASSERT_EQ(gpu::cellTriangleIndex(rows[row]), id);
    gpu::GpuTriangle t = packedTriangle(packed, id);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(rows[row][axis], std::bit_cast<uint32_t>(t.v0[axis]));
        EXPECT_EQ(rows[row + 1][axis], std::bit_cast<uint32_t>(t.v1[axis]));
        EXPECT_EQ(rows[row + 2][axis], std::bit_cast<uint32_t>(t.v2[axis]));
        // And the scene's own vertex, as a float.
        EXPECT_EQ(rows[row + 1][axis],
                  std::bit_cast<uint32_t>(float(scene.triangles[id].p[1][axis])));
    }
    EXPECT_EQ(rows[row + 1].w, 0u);
    EXPECT_EQ(rows[row + 2].w, 0u);
}

TEST(CellTriangles, AreTheListedTrianglesInListOrder) {
    Scene scene = triangleScene();
    Grid grid = buildGrid(scene, parseGridOption("6"));
    PackedScene packed = packScene(scene, grid, true);
    EXPECT_FALSE(packed.cellRecords);
    std::vector<glm::uvec4> rows(cellTriangleRows(packed));
    writeCellTriangles(packed, rows);
    ASSERT_EQ(rows.size(), 3 * grid.cellPrimitives.size());
    ASSERT_EQ(cellTriangleRows(grid, true), rows.size());
    ASSERT_GT(grid.cellPrimitives.size(), scene.triangles.size()) << "some listed twice";
    EXPECT_THROW(writeCellTriangles(packed, std::span(rows).first(rows.size() - 1)), Error);
    for (size_t k = 0; k < grid.cellPrimitives.size(); ++k)
        expectCellTriangle(scene, grid, packed, rows, 3 * k, k);
    EXPECT_EQ(cellTriangleRows(packScene(scene, grid)), 0u);
    EXPECT_EQ(cellTriangleRows(grid, false), 0u);
    Scene withSphere = scene;
    withSphere.spheres.push_back(Sphere{{0.0, 3.0, 0.0}, 0.5f, 0});
    Grid withSphereGrid = buildGrid(withSphere);
    EXPECT_THROW(packScene(withSphere, withSphereGrid, true), Error);
}

// On an adaptive grid: every cell's record (its box row, then its triangles), at the row that
// the voxel map's leaf for the cell names, the rows filling the array exactly once.
TEST(CellTriangles, AdaptiveGridCellsAreRecordsTheVoxelMapNames) {
    Scene scene = triangleScene();
    Grid grid = buildGrid(scene, parseGridOption("adaptive"));
    ASSERT_TRUE(grid.adaptive());
    PackedScene packed = packScene(scene, grid, true);
    ASSERT_TRUE(packed.cellRecords);
    EXPECT_FALSE(packScene(scene, grid).cellRecords);
    std::vector<glm::uvec4> rows(cellTriangleRows(packed));
    ASSERT_EQ(rows.size(), grid.cellCount() + 3 * grid.cellPrimitives.size());
    ASSERT_EQ(cellTriangleRows(grid, true), rows.size());
    writeCellTriangles(packed, rows);
    EXPECT_THROW(writeCellTriangles(packed, std::span(rows).first(rows.size() - 1)), Error);

    // Each leaf names the record of the cell it named in the grid; splits are unchanged.
    ASSERT_EQ(packed.gridEntries.size(), grid.entries.size());
    std::vector<uint32_t> recordOf(grid.cellCount(), ~0u);
    for (size_t i = 0; i < grid.entries.size(); ++i) {
        uint32_t entry = grid.entries[i], packedEntry = packed.gridEntries[i];
        ASSERT_EQ(gpu::entrySplit(packedEntry), gpu::entrySplit(entry));
        if (gpu::entrySplit(entry) != 0) {
            EXPECT_EQ(packedEntry, entry);
            continue;
        }
        uint32_t cell = gpu::entryTarget(entry);
        ASSERT_LT(cell, recordOf.size());
        EXPECT_TRUE(recordOf[cell] == ~0u || recordOf[cell] == gpu::entryTarget(packedEntry))
            << "one record a cell";
        recordOf[cell] = gpu::entryTarget(packedEntry);
    }
    // The records, in cell order, cover the rows exactly.
    size_t next = 0;
    for (uint32_t c = 0; c < grid.cellCount(); ++c) {
        SCOPED_TRACE("cell " + std::to_string(c));
        uint32_t first = grid.cellStart[c], count = grid.cellStart[c + 1] - first;
        if (recordOf[c] != ~0u) {
            EXPECT_EQ(recordOf[c], next);
        }
        ASSERT_EQ(gpu::cellRecordRow(c, first), next);
        const glm::uvec4 &box = rows[next];
        EXPECT_EQ(gpu::cellBoxMin(box), gpu::cellBoxMin(grid.cellBoxes[c]));
        EXPECT_EQ(gpu::cellBoxMax(box), gpu::cellBoxMax(grid.cellBoxes[c]));
        ASSERT_EQ(gpu::cellRecordCount(box), count);
        for (uint32_t k = 0; k < count; ++k) {
            ASSERT_EQ(gpu::cellRecordTriangleRow(uint32_t(next), k), next + 1 + 3 * k);
            expectCellTriangle(scene, grid, packed, rows, next + 1 + 3 * k, first + k);
        }
        next += 1 + 3 * size_t(count);
    }
    EXPECT_EQ(next, rows.size());
    EXPECT_EQ(std::count(recordOf.begin(), recordOf.end(), ~0u), 0) << "every cell has a leaf";
}

TEST(CellTriangles, ChosenOnlyWhereTheCellsListTrianglesAndTheyFit) {
    Scene scene = triangleScene();
    Grid grid = buildGrid(scene);
    uint64_t texels = 3 * grid.cellPrimitives.size();
    TracerOptions options;
    EXPECT_TRUE(chooseFeatures(scene, grid, options).cellTriangles);
    EXPECT_TRUE(chooseFeatures(scene, grid, options, texels).cellTriangles);
    EXPECT_FALSE(chooseFeatures(scene, grid, options, texels - 1).cellTriangles) << "too big";
    // An adaptive grid's records have a box row each cell too.
    Grid adaptive = buildGrid(scene, parseGridOption("adaptive"));
    uint64_t records = adaptive.cellCount() + 3 * adaptive.cellPrimitives.size();
    EXPECT_TRUE(chooseFeatures(scene, adaptive, options, records).cellTriangles);
    EXPECT_FALSE(chooseFeatures(scene, adaptive, options, records - 1).cellTriangles) << "too big";
    EXPECT_FALSE(chooseFeatures(scene, grid, options).backgroundOnly().cellTriangles);
    TracerOptions off = options;
    off.cellPrimitives = false;
    EXPECT_FALSE(chooseFeatures(scene, grid, off).cellTriangles);
    TracerOptions storage = options;
    storage.texelBuffers = false;
    EXPECT_FALSE(chooseFeatures(scene, grid, storage).cellTriangles);
    Scene withSphere = scene;
    withSphere.spheres.push_back(Sphere{{0.0, 3.0, 0.0}, 0.5f, 0});
    EXPECT_FALSE(chooseFeatures(withSphere, buildGrid(withSphere), options).cellTriangles);
    Scene withInstance = scene;
    withInstance.prototypes.push_back(
        MeshPrototype{"copy", scene.triangles, scene.triangleShading});
    withInstance.instances.push_back(Instance{});
    EXPECT_FALSE(chooseFeatures(withInstance, grid, options).cellTriangles);
}

TEST(CellSpheres, AreTheListedSpheresInListOrder) {
    Scene scene = sphereScene();
    for (const GridOptions &options : {parseGridOption("6"), parseGridOption("adaptive")}) {
        Grid grid = buildGrid(scene, options);
        PackedScene packed = packScene(scene, grid, false, true);
        ASSERT_EQ(packed.cellSpheres.size(), grid.cellPrimitives.size());
        ASSERT_GE(packed.cellSpheres.size(), scene.spheres.size());
        for (size_t k = 0; k < packed.cellSpheres.size(); ++k)
            EXPECT_EQ(packed.cellSpheres[k], packed.spheres[grid.cellPrimitives[k]].centerRadius);
        EXPECT_TRUE(packScene(scene, grid).cellSpheres.empty());
    }
    Grid six = buildGrid(scene, parseGridOption("6"));
    EXPECT_GT(packScene(scene, six, false, true).cellSpheres.size(), scene.spheres.size())
        << "some listed twice";
    Scene stability = stabilityScene();
    Grid stabilityGrid = buildGrid(stability);
    EXPECT_THROW(packScene(stability, stabilityGrid, false, true), Error);
}

TEST(CellSpheres, ChosenOnlyWhereTheCellsListSpheresAndTheyFit) {
    Scene scene = sphereScene();
    Grid grid = buildGrid(scene);
    TracerOptions options;
    TracerFeatures f = chooseFeatures(scene, grid, options);
    EXPECT_TRUE(f.cellSpheres);
    EXPECT_FALSE(f.cellTriangles);
    uint64_t entries = grid.cellPrimitives.size();
    EXPECT_TRUE(chooseFeatures(scene, grid, options, entries).cellSpheres);
    EXPECT_FALSE(chooseFeatures(scene, grid, options, entries - 1).cellSpheres) << "too big";
    EXPECT_FALSE(f.backgroundOnly().cellSpheres);
    TracerOptions off = options;
    off.cellPrimitives = false;
    EXPECT_FALSE(chooseFeatures(scene, grid, off).cellSpheres);
    TracerFeatures mixed = chooseFeatures(stabilityScene(), buildGrid(stabilityScene()), options);
    EXPECT_FALSE(mixed.cellSpheres || mixed.cellTriangles) << "spheres and triangles";
}

// With and without cell primitives: the same frame on an adaptive and a regular grid (depth 4),
// and resumed on `resumedGrid` with a lane budget small enough to interrupt walks everywhere.
void expectCellPrimitivesChangeNoPixel(vk::Context &context, const Scene &scene,
                                       const char *resumedGrid, uint32_t resumeBudget) {
    TracerOptions resumed;
    resumed.resumable = true;
    resumed.resumeLaneBudget = resumeBudget;
    resumed.resumeMemoryBytes = 20 << 10;
    struct Case {
        const char *grid;
        TracerOptions options;
        uint32_t depth;
    };
    for (const Case &c :
         {Case{"adaptive", {}, 4}, Case{"6", {}, 4}, Case{resumedGrid, resumed, 2}}) {
        SCOPED_TRACE(std::string(c.grid) + (c.options.resumable ? ", resumed" : ""));
        TracerOptions withCells = c.options, withIds = c.options;
        withCells.writeAov = withIds.writeAov = true;
        withIds.cellPrimitives = false;
        GridOptions grid = parseGridOption(c.grid);
        GpuRender cells = renderGpu(context, scene, 64, 48, 2, c.depth, grid, withCells);
        GpuRender ids = renderGpu(context, scene, 64, 48, 2, c.depth, grid, withIds);
        expectSameFrame(cells, ids);
        EXPECT_GT(cells.frame.rays.secondary, 0u);
        EXPECT_EQ(cells.frame.resumeDispatches, ids.frame.resumeDispatches);
        if (c.options.resumable) { // more dispatches than one per tile and sample: interrupted
            ResumePlan plan = planResume(64, 48, c.depth, 1, true, resumed.resumeMemoryBytes);
            uint32_t tiles = ((64 + plan.tileWidth - 1) / plan.tileWidth) *
                             ((48 + plan.tileHeight - 1) / plan.tileHeight);
            EXPECT_GT(cells.frame.resumeDispatches, 2 * tiles);
        }
    }
}

class CellPrimitivesRender : public GpuTest {};

TEST_F(CellPrimitivesRender, TrianglesChangeNoPixel) {
    expectCellPrimitivesChangeNoPixel(context(), triangleScene(), "adaptive", 300);
}

TEST_F(CellPrimitivesRender, SpheresChangeNoPixel) {
    expectCellPrimitivesChangeNoPixel(context(), sphereScene(), "6", 120);
}

} // namespace
} // namespace prism::test
