// Buffer layouts shared by the host (C++) and the tracer (GLSL), std430. Every member is a
// vec4/uvec4 (or a 64-bit counter) so the two agree without padding rules; the static_asserts
// below pin them down. Fields are packed four to a vector and read through the named accessors
// next to each struct, on both sides, never by lane.
#ifndef PRISM_GPU_TYPES_H
#define PRISM_GPU_TYPES_H
#include "glsl_compat.h"
#include "primitive_kinds.h"
#include "profile_phases.h"

PRISM_NAMESPACE_BEGIN

// Secondary/shadow ray origins move off the surface by this fraction of max|P_i| (2^-18: some
// 32 float ulps, above the few ulps of error in a rebuilt hit point), so a scene behaves the
// same at any scale and distance from the origin. The CPU reference uses the same number.
#define PRISM_OFFSET_RELATIVE 3.814697265625e-06
#define PRISM_OFFSET_FLOOR 1e-30

// Material indices travel in float lanes, exact below 2^24 (the packer refuses more).
PRISM_INLINE uint indexFromFloat(float lane) {
    return uint(lane);
}

// Read by the shader as a std140 uniform block (trace_bindings.glsl), where std140 and std430
// agree only because every member is a 16-byte vector: keep it so.
struct GpuSceneHeader {
    vec4 gridMin;     // xyz: grid bounds min
    vec4 gridMax;     // xyz: grid bounds max
    vec4 cellSize;    // xyz: size of one cell; w unused
    uvec4 gridRes;    // xyz: cells per axis; w: cell count
    uvec4 counts;     // x: spheres, y: planes, z: triangles, w: lights (host and tests only:
                      // the shader's loop bounds come in GpuFrameParams::seedsAndLoops)
    uvec4 idEnd;      // [kind]: end of that finite kind's grid id range (primitive_kinds.h)
    vec4 background;  // rgb
    vec4 ambient;     // rgb: scene ambient light
    vec4 voxelSize;   // adaptive grid: xyz size of one voxel
    uvec4 voxels;     // adaptive grid: xyz voxels per axis, w: voxels per top cell (log2)
    vec4 environment; // x: texture index (-1: none), y: intensity, z: rotation about +y (rad)
};

// An adaptive-grid cell's box in voxels: 16 bits a coordinate (accel/grid.h, packCellBox).
PRISM_INLINE ivec3 cellBoxMin(PRISM_IN(uvec4) box) {
    return ivec3(int(box.x & 0xFFFFu), int(box.x >> 16u), int(box.y & 0xFFFFu));
}
PRISM_INLINE ivec3 cellBoxMax(PRISM_IN(uvec4) box) {
    return ivec3(int(box.y >> 16u), int(box.z & 0xFFFFu), int(box.z >> 16u));
}
// On the GPU a box's w is the cell's first entry in the primitive lists (its cellStart), so a
// step of the walk reads one offset less (render/scene_packing.cpp writes it). In a cell record
// (below) it is the cell's count instead.
PRISM_INLINE uint cellBoxFirstPrimitive(PRISM_IN(uvec4) box) {
    return box.w;
}
// A voxel-map entry: a split into 2^split parts per axis (0: a leaf) and what it points at.
PRISM_INLINE uint entrySplit(uint entry) {
    return entry & 15u;
}
PRISM_INLINE uint entryTarget(uint entry) { // first child entry, or the leaf's cell
    return entry >> 4u;
}

struct GpuSphere {
    vec4 centerRadius; // xyz centre, w radius
    vec4 attributes;   // x: material index
};
PRISM_INLINE uint sphereMaterial(PRISM_IN(GpuSphere) s) {
    return indexFromFloat(s.attributes.x);
}

struct GpuPlane {
    vec4 normalOffset; // xyz unit normal, w = dot(normal, point)
    vec4 point;        // xyz a point on the plane; w: material index
};
PRISM_INLINE uint planeMaterial(PRISM_IN(GpuPlane) p) {
    return indexFromFloat(p.point.w);
}

// Vertices only: the intersection loop reads 48 bytes per triangle; shading data lives apart.
struct GpuTriangle {
    vec4 v0; // w: material index
    vec4 v1;
    vec4 v2;
};
PRISM_INLINE uint triangleMaterial(PRISM_IN(GpuTriangle) t) {
    return indexFromFloat(t.v0.w);
}

// A cell-list entry of a triangle-only scene (kBindingCellTriangles): the triangle's vertices
// in the order of the cell lists, so the walk reads the triangle where it reads the list and
// needs no primitive id. Integer texels with the floats as bits: read back exactly.
struct GpuCellTriangle {
    uvec4 p0; // xyz: vertex 0 (float bits); w: the triangle's index in the triangle array
    uvec4 p1; // xyz: vertex 1
    uvec4 p2; // xyz: vertex 2
};
PRISM_INLINE uint cellTriangleIndex(PRISM_IN(uvec4) p0) {
    return p0.w;
}
// The adaptive grid's cell records (CELL_TRIANGLES on an adaptive grid). The cell triangle array
// is then read as rows of 16 bytes: each cell, in cell order, has its box row (cellBoxMin/Max;
// w: how many triangles it lists), then its triangles (three rows each, as GpuCellTriangle), and
// the voxel map's leaves name the box row. A walk's step reads its cell's box and triangles from
// one place, most often the same or the next cache line, instead of from two arrays one after
// the other: on 1M triangles, whose arrays are far larger than the caches, that is a tenth of
// the frame (docs/benchmarks.md).
PRISM_INLINE uint cellRecordCount(PRISM_IN(uvec4) boxRow) {
    return boxRow.w;
}
// Row 0 of the k-th triangle of the record whose box row is `record`.
PRISM_INLINE uint cellRecordTriangleRow(uint record, uint k) {
    return record + 1u + 3u * k;
}
// The box row of cell `cell` whose list starts at entry `cellStart`: every cell before it has a
// box row, and three rows per entry of theirs.
PRISM_INLINE uint cellRecordRow(uint cell, uint cellStart) {
    return cell + 3u * cellStart;
}

// A placement of a mesh prototype (scene.h, Instance): the similarity both ways, as the rows of
// 3x4 matrices (p' = (dot(row0.xyz, p) + row0.w, ...)). The walk takes rays into the prototype's
// space (toObject); shading takes the hit triangle out of it (toWorld).
struct GpuInstance {
    vec4 toObject0;
    vec4 toObject1;
    vec4 toObject2;
    vec4 toWorld0;
    vec4 toWorld1;
    vec4 toWorld2;
    vec4 info; // x: the prototype (its GpuMeshGrid), y: material for every face (-1: its own)
};
// On the info vector alone: the tracer reads an instance a row at a time (instanceRow).
PRISM_INLINE uint instancePrototype(PRISM_IN(vec4) info) {
    return indexFromFloat(info.x);
}
PRISM_INLINE bool instanceOverridesMaterial(PRISM_IN(vec4) info) {
    return info.y >= 0.0f;
}
PRISM_INLINE uint instanceMaterial(PRISM_IN(vec4) info) {
    return indexFromFloat(info.y);
}

// A prototype's own regular grid, in its space (accel/grid.h, Grid::meshGrids). Its cells'
// offsets follow the scene grid's in the cell-offset array, and its cells list the prototype's
// triangles by their index in the triangle array.
struct GpuMeshGrid {
    vec4 gridMin;  // xyz
    vec4 gridMax;  // xyz
    vec4 cellSize; // xyz
    uvec4 res;     // xyz: cells per axis; w: its first cell's entry in the cell offsets
};
PRISM_INLINE uint meshGridFirstCell(PRISM_IN(GpuMeshGrid) g) {
    return g.res.w;
}

struct GpuTriangleShading {
    vec4 n0; // vertex normals; n0.w = 1 when present
    vec4 n1; // n1.w = 1 when texture coordinates are present
    vec4 n2;
    vec4 uv01; // xy: uv0, zw: uv1
    vec4 uv2;  // xy: uv2
};
PRISM_INLINE bool shadingHasNormals(PRISM_IN(GpuTriangleShading) s) {
    return s.n0.w != 0.0f;
}
PRISM_INLINE bool shadingHasUVs(PRISM_IN(GpuTriangleShading) s) {
    return s.n1.w != 0.0f;
}

struct GpuMaterial {
    vec4 colorAmbient; // rgb colour, a: ambient coefficient
    vec4 lighting;     // x diffuse, y specular, z shininess, w reflect
    vec4 optics;       // x transmit, y ior, z texture index (-1: none)
    vec4 maps;         // x normal map index, y bump map index (-1: none), z bump multiplier
};
PRISM_INLINE vec3 materialColor(PRISM_IN(GpuMaterial) m) {
    return vec3(m.colorAmbient);
}
PRISM_INLINE float materialAmbient(PRISM_IN(GpuMaterial) m) {
    return m.colorAmbient.w;
}
PRISM_INLINE float materialDiffuse(PRISM_IN(GpuMaterial) m) {
    return m.lighting.x;
}
PRISM_INLINE float materialSpecular(PRISM_IN(GpuMaterial) m) {
    return m.lighting.y;
}
PRISM_INLINE float materialShininess(PRISM_IN(GpuMaterial) m) {
    return m.lighting.z;
}
PRISM_INLINE float materialReflect(PRISM_IN(GpuMaterial) m) {
    return m.lighting.w;
}
PRISM_INLINE float materialTransmit(PRISM_IN(GpuMaterial) m) {
    return m.optics.x;
}
PRISM_INLINE float materialIor(PRISM_IN(GpuMaterial) m) {
    return m.optics.y;
}
PRISM_INLINE bool materialHasTexture(PRISM_IN(GpuMaterial) m) {
    return m.optics.z >= 0.0f;
}
PRISM_INLINE uint materialTexture(PRISM_IN(GpuMaterial) m) {
    return uint(m.optics.z);
}
PRISM_INLINE bool materialHasNormalMap(PRISM_IN(GpuMaterial) m) {
    return m.maps.x >= 0.0f;
}
PRISM_INLINE uint materialNormalMap(PRISM_IN(GpuMaterial) m) {
    return uint(m.maps.x);
}
PRISM_INLINE bool materialHasBumpMap(PRISM_IN(GpuMaterial) m) {
    return m.maps.y >= 0.0f;
}
PRISM_INLINE uint materialBumpMap(PRISM_IN(GpuMaterial) m) {
    return uint(m.maps.y);
}
PRISM_INLINE float materialBumpScale(PRISM_IN(GpuMaterial) m) {
    return m.maps.z;
}

struct GpuLight {
    vec4 positionRadius; // xyz position, w radius (0: point light)
    vec4 color;
};
PRISM_INLINE vec3 lightPosition(PRISM_IN(GpuLight) l) {
    return vec3(l.positionRadius);
}
PRISM_INLINE float lightRadius(PRISM_IN(GpuLight) l) {
    return l.positionRadius.w;
}
PRISM_INLINE vec3 lightColor(PRISM_IN(GpuLight) l) {
    return vec3(l.color);
}

struct GpuTexture {
    uvec4 info; // x: first texel in the texel array, y: width, z: height
};
PRISM_INLINE uint textureFirstTexel(PRISM_IN(GpuTexture) t) {
    return t.info.x;
}
PRISM_INLINE uint textureWidth(PRISM_IN(GpuTexture) t) {
    return t.info.y;
}
PRISM_INLINE uint textureHeight(PRISM_IN(GpuTexture) t) {
    return t.info.z;
}

// Ray counts, one cache line of them: the tracer spreads its atomics over kRayCountSlots such
// lines by workgroup, and the host adds them up. Each lane adds its own shadow and secondary
// counts, and one lane a workgroup its tile's camera rays: summing them over the subgroup first
// (subgroupAdd, a loop over the lanes on lavapipe) cost 3-6% of a frame (docs/benchmarks.md,
// "Ray counts without a subgroup sum").
struct GpuRayCounts {
    uint64_t primary;
    uint64_t shadow;
    uint64_t secondary;
    uint64_t loopCut; // pixels lavapipe's loop limit cut short (loop_limit.glsl)
    uint64_t unused[4];
};
PRISM_CONST(uint, kRayCountSlots, 64u);

// Counters the tracer adds to with atomics (64-bit: a frame can trace billions of rays).
struct GpuStats {
    // Resumable tracing (resume.glsl): pixels whose sample is not finished after this
    // dispatch, and pixels that cannot finish (more walks than their log holds, or a budget
    // spent before the replay reaches the walk in progress).
    uint64_t unfinishedPixels;
    uint64_t stuckPixels;
    uint64_t phaseNs[kProfileSlots]; // with PRISM_PROFILE: time per phase (profile_phases.h)
    uint64_t unused[4];              // the slots start on a cache line of their own
    GpuRayCounts rayCounts[kRayCountSlots];
};

// Per-frame parameters (push constants, 128 bytes at most).
struct GpuFrameParams {
    vec4 eye;     // xyz: camera position; w: 1 for parallel projection
    vec4 forward; // xyz: unit view direction; w: the sampling seed (frameSeed)
    vec4 du;      // xyz: right scaled by h*a (perspective) or (H/2)*a (ortho); w: store origin x
    vec4 dv;      // xyz: true up scaled by h (perspective) or H/2 (ortho); w: store origin y
    uvec4 image;  // x width, y height, z this dispatch's sample index, w samples per pixel
    // x: max depth, y: kLoopProbeRuns. Resumable tracing: z the tile origin x | y << 16, w the
    // walk log size; otherwise z, w: the dispatch's range of the frame's tile list.
    uvec4 control;
    // The pixel jitter's parts that are the same for every pixel of a dispatch, computed once by
    // the host (render/frame_params.h): in the shader they were integer divisions and loops,
    // which lavapipe runs lane by lane for every pixel.
    vec4 strata; // xy: this sample's stratum (column, row); zw: columns, rows
    // x, y: sampleSeed(sample, PRISM_DIM_PIXEL_X / _Y) (shared/sampling.h). z, w: the plane and
    // light loops' bounds (the header has them too). They come here, not from the header's
    // uniform block, because lavapipe recompiles a shader whenever the value of a uniform that
    // bounds a loop may have changed: with the counts read from the header it compiled the
    // tracer anew at every frame (10-18% of a frame on scenes with planes, and memory).
    uvec4 seedsAndLoops;
};
PRISM_INLINE uint framePlaneCount(PRISM_IN(GpuFrameParams) f) {
    return f.seedsAndLoops.z;
}
PRISM_INLINE uint frameLightCount(PRISM_IN(GpuFrameParams) f) {
    return f.seedsAndLoops.w;
}
PRISM_INLINE bool isParallelCamera(PRISM_IN(GpuFrameParams) f) {
    return f.eye.w != 0.0f;
}
// Where the accumulation and AOV images start in the image: a region's render (render/
// image_region.h) holds only the tiles round it. Carried in du.w and dv.w, which the camera does
// not use (push constants are full at 128 bytes), as floats: exact below 2^24 pixels.
PRISM_INLINE uvec2 frameStoreOrigin(PRISM_IN(GpuFrameParams) f) {
    return uvec2(uint(f.du.w), uint(f.dv.w));
}
// The sampling seed (shared/sampling.h: samplingKey), in forward.w, which the camera does not
// use, as a float: exact below 2^24 (RayTracer::setSeed refuses larger seeds).
PRISM_INLINE uint frameSeed(PRISM_IN(GpuFrameParams) f) {
    return uint(f.forward.w);
}
PRISM_CONST(uint, kMaxSeed, 16777215u);
PRISM_INLINE uint frameSampleIndex(PRISM_IN(GpuFrameParams) f) {
    return f.image.z;
}
PRISM_INLINE uint frameSamplesPerPixel(PRISM_IN(GpuFrameParams) f) {
    return f.image.w;
}
PRISM_INLINE uint frameMaxDepth(PRISM_IN(GpuFrameParams) f) {
    return f.control.x;
}
// Iterations of the loop that tells whether lavapipe cut the invocation (loop_limit.glsl).
PRISM_CONST(uint, kLoopProbeRuns, 2u);
PRISM_INLINE uint frameLoopProbe(PRISM_IN(GpuFrameParams) f) {
    return f.control.y;
}
// Resumable tracing: the first pixel of the tile a dispatch traces.
PRISM_INLINE uint frameTileOriginX(PRISM_IN(GpuFrameParams) f) {
    return f.control.z & 0xFFFFu;
}
PRISM_INLINE uint frameTileOriginY(PRISM_IN(GpuFrameParams) f) {
    return f.control.z >> 16u;
}
// Otherwise: the entries [start, end) of the tile list (kBindingTileList) that a dispatch's
// workgroups trace, one each.
PRISM_INLINE uint frameTileListStart(PRISM_IN(GpuFrameParams) f) {
    return f.control.z;
}
PRISM_INLINE uint frameTileListEnd(PRISM_IN(GpuFrameParams) f) {
    return f.control.w;
}
// Resumable tracing: walk results each pixel's log holds (resume.glsl).
PRISM_INLINE uint frameWalkLogSize(PRISM_IN(GpuFrameParams) f) {
    return f.control.w;
}

// Resumable tracing (shaders/resume.glsl): where a pixel's sample stands between dispatches.
struct GpuResumeRecord {
    // x: walks whose results are in the log (the next walk is the one in progress), y: 1 once
    // the sample is finished, z: tests the walk in progress has done in its cell, w: 1 when
    // there is a walk in progress.
    uvec4 progress;
    uvec4 bestHit; // the walk in progress's closest hit so far, packed as in the log
    uvec4 walker;  // xyz: its cell (regular grid) or voxel (adaptive) on entering the cell;
                   // w: the best hit's instance (as the log's second word, resume.glsl)
    uvec4 walkerT; // float bits: xyz tNext (regular) or x the walk's t there (adaptive)
};

PRISM_NAMESPACE_END

#ifdef __cplusplus
#include <cstddef>
namespace prism::gpu {
static_assert(sizeof(GpuSceneHeader) == 176);
static_assert(offsetof(GpuSceneHeader, environment) == 160);
static_assert(offsetof(GpuSceneHeader, voxels) == 144);
static_assert(offsetof(GpuSceneHeader, gridRes) == 48);
static_assert(offsetof(GpuSceneHeader, idEnd) == 80);
static_assert(offsetof(GpuSceneHeader, ambient) == 112);
static_assert(sizeof(GpuSphere) == 32);
static_assert(sizeof(GpuPlane) == 32);
static_assert(sizeof(GpuTriangle) == 48);
static_assert(sizeof(GpuCellTriangle) == 48);
static_assert(sizeof(GpuTriangleShading) == 80);
static_assert(sizeof(GpuInstance) == 112);
static_assert(offsetof(GpuInstance, toWorld0) == 48);
static_assert(offsetof(GpuInstance, info) == 96);
static_assert(sizeof(GpuMeshGrid) == 64);
static_assert(offsetof(GpuMeshGrid, res) == 48);
static_assert(offsetof(GpuTriangleShading, uv01) == 48);
static_assert(sizeof(GpuMaterial) == 64);
static_assert(offsetof(GpuMaterial, optics) == 32);
static_assert(offsetof(GpuMaterial, maps) == 48);
static_assert(sizeof(GpuLight) == 32);
static_assert(sizeof(GpuTexture) == 16);
static_assert(sizeof(GpuRayCounts) == 64);
static_assert(offsetof(GpuRayCounts, loopCut) == 24);
static_assert(offsetof(GpuStats, stuckPixels) == 8);
static_assert(offsetof(GpuStats, phaseNs) == 16);
static_assert(offsetof(GpuStats, rayCounts) == 128);
static_assert(sizeof(GpuStats) == 128 + 64 * kRayCountSlots);
static_assert(sizeof(GpuResumeRecord) == 64);
static_assert(sizeof(GpuFrameParams) == 128);
static_assert(offsetof(GpuFrameParams, seedsAndLoops) == 112);
static_assert(offsetof(GpuFrameParams, image) == 64);
static_assert(sizeof(GpuFrameParams) <= 128, "push constants are limited to 128 bytes");
} // namespace prism::gpu
#endif
#endif
