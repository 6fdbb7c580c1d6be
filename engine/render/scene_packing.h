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
    std::vector<gpu::GpuTriangle> triangles;
    std::vector<gpu::GpuTriangleShading> triangleShading; // empty when no triangle needs it
    std::vector<gpu::GpuMaterial> materials;
    std::vector<gpu::GpuLight> lights;
    std::vector<gpu::GpuTexture> textures;
    std::vector<glm::vec4> texels;
    std::vector<uint32_t> cellStart;
    std::vector<uint32_t> cellPrimitives;
    // With cellTriangles: each cell entry's triangle (gpu::GpuCellTriangle, 48 bytes), in list
    // order. Not held here: writeCellTriangles writes it straight into the device's array at
    // upload, as it is the largest array by far (256 of the 390 MB of 1M triangles).
    bool cellTriangles = false;
    std::vector<glm::vec4> cellSpheres; // with cellSpheres only: each entry's centre and radius
    std::vector<uint32_t> gridEntries;  // adaptive grid only
    std::vector<glm::uvec4> cellBoxes;  // adaptive grid only
    std::vector<gpu::GpuInstance> instances;
    std::vector<gpu::GpuMeshGrid> meshGrids; // one per prototype
};

// The triangle array holds the scene's triangles, then each prototype's; the cell arrays the
// scene grid, then each prototype's grid (gpu::GpuMeshGrid says where).
// Positions become 32-bit floats here: give it a scene centred on the camera
// (scene/scene_origin.h), with the grid built from that same scene.
// With cellTriangles (a scene whose grid lists triangles only: TracerFeatures::cellTriangles)
// each cell entry's triangle is also stored in list order; likewise with cellSpheres.
PackedScene packScene(const Scene &scene, const Grid &grid, bool cellTriangles = false,
                      bool cellSpheres = false);

// Entries of the cell triangle array: one per cell entry with cellTriangles, else none.
uint64_t cellTriangleCount(const PackedScene &packed);
// Writes the cell triangle array, cellTriangleCount(packed) entries, into `out`, from
// packed.triangles and packed.cellPrimitives. Throws prism::Error for any other size.
void writeCellTriangles(const PackedScene &packed, std::span<gpu::GpuCellTriangle> out);

} // namespace prism
