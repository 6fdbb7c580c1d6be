// The tracer's interface with the host, named once for both languages: descriptor bindings
// (set 0) and specialization-constant ids of trace.comp. shaders/trace_bindings.glsl declares
// the resources with these numbers; engine/render binds them by the same names. The descriptor
// types are the shader's own: a host binding of the wrong type fails Vulkan validation, which is
// on in every test (docs/design.md, "Shader-host contracts").
#ifndef PRISM_TRACE_INTERFACE_H
#define PRISM_TRACE_INTERFACE_H
#include "glsl_compat.h"

PRISM_NAMESPACE_BEGIN

// Images.
PRISM_CONST(uint, kBindingAccumImage, 0u); // rgba32f: sum of sample radiance, alpha = samples
PRISM_CONST(uint, kBindingAovImage, 1u);   // rgba32f: xyz normal, w depth
// Storage buffers.
PRISM_CONST(uint, kBindingStats, 2u); // GpuStats, written with atomics
PRISM_CONST(uint, kBindingHeader, 3u);
PRISM_CONST(uint, kBindingSpheres, 4u);
PRISM_CONST(uint, kBindingPlanes, 5u);
PRISM_CONST(uint, kBindingTriangles, 6u);
PRISM_CONST(uint, kBindingTriangleShading, 7u);
PRISM_CONST(uint, kBindingMaterials, 8u);
PRISM_CONST(uint, kBindingLights, 9u);
PRISM_CONST(uint, kBindingCellStart, 10u);
PRISM_CONST(uint, kBindingCellPrimitives, 11u);
PRISM_CONST(uint, kBindingTextures, 12u);
PRISM_CONST(uint, kBindingTexels, 13u);
// Uniform texel buffers over the same arrays (read instead when TEXEL_BUFFERS is on).
PRISM_CONST(uint, kBindingCellStartTexels, 14u);       // r32ui
PRISM_CONST(uint, kBindingCellPrimitiveTexels, 15u);   // r32ui
PRISM_CONST(uint, kBindingSphereTexels, 16u);          // rgba32f, 2 per GpuSphere
PRISM_CONST(uint, kBindingTriangleTexels, 17u);        // rgba32f, 3 per GpuTriangle
PRISM_CONST(uint, kBindingImageTexels, 18u);           // rgba32f, the texture texels
PRISM_CONST(uint, kBindingTriangleShadingTexels, 19u); // rgba32f, 5 per GpuTriangleShading
PRISM_CONST(uint, kBindingGridEntries, 20u);           // adaptive grid: the voxel map
PRISM_CONST(uint, kBindingCellBoxes, 21u);             // adaptive grid: each cell's box in voxels
PRISM_CONST(uint, kBindingGridEntryTexels, 22u);       // r32ui
PRISM_CONST(uint, kBindingCellBoxTexels, 23u);         // rgba32ui
// Resumable tracing (resume.glsl): a GpuResumeRecord and a walk log per pixel of the tile.
PRISM_CONST(uint, kBindingResumeRecords, 24u);
PRISM_CONST(uint, kBindingWalkLog, 25u); // uvec4 per walk result, frameWalkLogSize per pixel
// Instances (scene.h): the placements, and their prototypes' grids.
PRISM_CONST(uint, kBindingInstances, 26u);
PRISM_CONST(uint, kBindingMeshGrids, 27u);
PRISM_CONST(uint, kBindingInstanceTexels, 28u); // rgba32f, 7 per GpuInstance
// Texel views of the small arrays too: lavapipe reads a storage buffer lane by lane (a loop of
// 8, a bounds check each), a texel buffer with one gather (docs/benchmarks.md).
PRISM_CONST(uint, kBindingPlaneTexels, 29u);    // rgba32f, 2 per GpuPlane
PRISM_CONST(uint, kBindingMaterialTexels, 30u); // rgba32f, 4 per GpuMaterial
PRISM_CONST(uint, kBindingLightTexels, 31u);    // rgba32f, 2 per GpuLight
PRISM_CONST(uint, kBindingMeshGridTexels, 32u); // rgba32ui, 4 per GpuMeshGrid (floats as bits)
PRISM_CONST(uint, kBindingTextureTexels, 33u);  // rgba32ui, 1 per GpuTexture
// Triangle-only scenes: each cell entry's triangle itself, in the order of the cell lists
// (GpuCellTriangle), so a test reads three texels and no primitive id (CELL_TRIANGLES).
PRISM_CONST(uint, kBindingCellTriangles, 34u);
PRISM_CONST(uint, kBindingCellTriangleTexels, 35u); // rgba32ui, 3 per cell entry
// The frame's tiles, x | y << 16 in tiles (render/traced_tiles.h): each dispatch but a
// resumable one traces a range of it, a workgroup per entry.
PRISM_CONST(uint, kBindingTileList, 36u); // r32ui
// Sphere-only grids: each cell entry's sphere (centre, radius) in the order of the cell lists, so
// a test reads one texel and no primitive id; the id of the nearest hit's entry is read once,
// after the walk (CELL_SPHERES).
PRISM_CONST(uint, kBindingCellSpheres, 37u);
PRISM_CONST(uint, kBindingCellSphereTexels, 38u); // rgba32f, 1 per cell entry
PRISM_CONST(uint, kTraceBindingCount, 39u);

// Specialization constants: features a scene does not use are compiled out.
PRISM_CONST(uint, kSpecKinds, 0u); // bit k: the scene has primitives of kind k
PRISM_CONST(uint, kSpecHasReflection, 1u);
PRISM_CONST(uint, kSpecHasTransmission, 2u);
PRISM_CONST(uint, kSpecHasTextures, 3u);
PRISM_CONST(uint, kSpecHasAreaLights, 4u);
PRISM_CONST(uint, kSpecHasVertexNormals, 5u);
PRISM_CONST(uint, kSpecHasShadows, 6u);
PRISM_CONST(uint, kSpecWriteAov, 7u);
PRISM_CONST(uint, kSpecHasEnvironment, 8u); // misses see Scene::environment, not the background
PRISM_CONST(uint, kSpecStackSize, 9u);      // 2 * maxDepth - 1
PRISM_CONST(uint, kSpecTexelBuffers, 10u);
PRISM_CONST(uint, kSpecAdaptiveGrid, 11u);   // walk the adaptive grid's cells, not a regular DDA
PRISM_CONST(uint, kSpecHasSurfaceMaps, 12u); // some material has a normal or bump map
PRISM_CONST(uint, kSpecCellTriangles, 15u);  // walk the cell triangle array (binding 35)
PRISM_CONST(uint, kSpecCellSpheres, 16u);    // walk the cell sphere array (binding 38)
// For the studies only (docs/studies, prism-bench variants): the methods Prism replaced, so that
// where they fail can be measured. At their defaults they fold away to Prism's own methods.
PRISM_CONST(uint, kSpecFixedRayOffset, 13u);    // float: 0 = relative offset; > 0: fixed, in units
PRISM_CONST(uint, kSpecTriangleTest, 14u);      // one of the kTriangleTest values below
PRISM_CONST(uint, kTriangleTestWatertight, 0u); // Woop, Benthin & Wald 2013 (Prism's)
PRISM_CONST(uint, kTriangleTestMollerTrumbore, 1u); // Moller & Trumbore 1997
// Only in the profiling build (PRISM_PROFILE): also time the primitive loops (profile.glsl).
PRISM_CONST(uint, kSpecProfileWalkDetail, 20u);
// Trace with a loop budget and resume where it ran out in the next dispatch (resume.glsl).
PRISM_CONST(uint, kSpecResumable, 21u);
PRISM_CONST(uint, kSpecResumeLaneBudget, 22u); // loop iterations a lane may charge per dispatch
// A subgroup's 8 lanes step through loops together, so its count is at most the sum of theirs.
// Each loop a subgroup enters runs once more than its lanes count (NIR's loops test at the top,
// gallivm's at the bottom, even with no lane active): resume.glsl charges every walk, bounce
// and light an extra 8 for the loops inside it, and every cell its passes with the voxel-map
// descent's levels. 8 x 7,900 leaves 2,300 of lavapipe's 65,535 for the few loops outside all
// of those. Should a cut happen anyway, the loop probe sees it and the sample is refused by
// name, never written wrong.
PRISM_CONST(uint, kResumeLaneBudget, 7900u);

PRISM_NAMESPACE_END

#endif
