#pragma once
// Turns the scene and its grid into the flat std430 arrays the tracer reads (shared/gpu_types.h).
// CPU only, so the packing is unit-tested without a device.
#include <cstdint>
#include <span>
#include <vector>

#include "accel/grid.h"
#include "scene/scene.h"
#include "shared/gpu_types.h"

namespace prism {

struct PackedScene {
    gpu::GpuSceneHeader header{};
    std::vector<gpu::GpuSphere> spheres;
    std::vector<gpu::GpuPlane> planes;
    // The triangles are not copied here either: writeTriangles and writeTriangleShading write
    // their records straight into the device's arrays from the scene's triangles (48 MB at 1M,
    // written once instead of packed and copied). The scene's list, then each prototype's.
    struct TriangleList {
        std::span<const Triangle> triangles;
        std::span<const TriangleShading> shading; // the records the triangles point to
    };
    std::vector<TriangleList> triangleLists;
    uint64_t triangleCount = 0;
    bool triangleShading = false; // every triangle has its shading record (normals, UVs, maps)
    std::vector<gpu::GpuMaterial> materials;
    std::vector<gpu::GpuLight> lights;
    std::vector<gpu::GpuTexture> textures;
    std::vector<glm::vec4> texels;
    // The grid's arrays are read where the grid holds them, not copied (73 of the ~800 MB a
    // warm 1M-triangle render faults in), unless the packing changes them: the prototypes'
    // grids appended, the leaves naming cell records. Then they view the owned vectors below.
    // So a PackedScene refers to its grid, which must outlive it (packScene refuses a
    // temporary grid).
    std::span<const uint32_t> cellStart;
    std::span<const uint32_t> cellPrimitives;
    // With cellTriangles: each cell entry's triangle (gpu::GpuCellTriangle, 48 bytes), in list
    // order; on an adaptive grid, each cell's record: its box row, then its triangles
    // (cellRecords; gpu::cellRecordRow). Not held here: writeCellTriangles writes it straight
    // into the device's array at upload, as it is the largest array by far (289 of the 360 MB
    // of 1M triangles).
    // The tracer then reads no primitive ids (cellPrimitives), and with cellRecords neither
    // cellStart nor cellBoxes: none of these is uploaded (render/scene_buffers.cpp).
    bool cellTriangles = false;
    bool cellRecords = false;
    std::vector<glm::vec4> cellSpheres; // with cellSpheres only: each entry's centre and radius
    // Adaptive grid only. With cellRecords the leaves name cell records, not cells, and the
    // boxes are written into the records.
    std::span<const uint32_t> gridEntries;
    // The grid's boxes as built: the device's array also holds each cell's first primitive in
    // w (gpu::cellBoxFirstPrimitive), which writeCellBoxes adds as it writes them.
    std::span<const glm::uvec4> cellBoxes;
    std::vector<gpu::GpuInstance> instances;
    std::vector<gpu::GpuMeshGrid> meshGrids; // one per prototype
    std::vector<uint32_t> ownedCellStart, ownedCellPrimitives, ownedGridEntries;

    PackedScene() = default;
    // Moved, the owned vectors keep their storage and the views stay valid; a copy's views
    // would point into the original.
    PackedScene(PackedScene &&) = default;
    PackedScene &operator=(PackedScene &&) = default;
    PackedScene(const PackedScene &) = delete;
    PackedScene &operator=(const PackedScene &) = delete;
};

// The triangle array holds the scene's triangles, then each prototype's; the cell arrays the
// scene grid, then each prototype's grid (gpu::GpuMeshGrid says where).
// Positions become 32-bit floats here: give it a scene centred on the camera
// (scene/scene_origin.h), with the grid built from that same scene.
// With cellTriangles (a scene whose grid lists triangles only: TracerFeatures::cellTriangles)
// each cell entry's triangle is also stored in list order; likewise with cellSpheres.
PackedScene packScene(const Scene &scene, const Grid &grid, bool cellTriangles = false,
                      bool cellSpheres = false);
// The packed scene views the scene's triangles and the grid's arrays: a scene or grid that
// would be gone at the end of the statement is refused at compile time.
PackedScene packScene(const Scene &scene, Grid &&grid, bool cellTriangles = false,
                      bool cellSpheres = false) = delete;
PackedScene packScene(Scene &&scene, const Grid &grid, bool cellTriangles = false,
                      bool cellSpheres = false) = delete;

// Triangle i of the packed triangle array (the scene's, then each prototype's) as the device
// holds it; prism::Error past the end.
gpu::GpuTriangle packedTriangle(const PackedScene &packed, uint64_t i);
// Write the triangle array (packed.triangleCount records) and, where packed.triangleShading,
// the shading array (as many) into `out`; prism::Error for any other size.
void writeTriangles(const PackedScene &packed, std::span<gpu::GpuTriangle> out);
void writeTriangleShading(const PackedScene &packed, std::span<gpu::GpuTriangleShading> out);

// Rows (16 bytes) of the cell triangle array: three per cell entry with cellTriangles, and one
// per cell more with cellRecords; else none.
uint64_t cellTriangleRows(const Grid &grid, bool cellTriangles);
uint64_t cellTriangleRows(const PackedScene &packed);
// Writes the cell triangle array, cellTriangleRows(packed) rows, into `out`, from
// the packed triangles and packed.cellPrimitives (and packed.cellBoxes for the records). Throws
// prism::Error for any other size.
void writeCellTriangles(const PackedScene &packed, std::span<glm::uvec4> out);
// Writes the device's cell box array, packed.cellBoxes with each cell's first primitive
// (packed.cellStart) in w, into `out` (packed.cellBoxes.size() rows; prism::Error otherwise).
void writeCellBoxes(const PackedScene &packed, std::span<glm::uvec4> out);

} // namespace prism
