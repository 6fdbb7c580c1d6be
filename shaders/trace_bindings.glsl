// The tracer's resources, declared with the names of shared/trace_interface.h, and the only
// code that indexes them: everything else reads the scene through the accessors below. An array
// that has a texel view is read through it whenever TEXEL_BUFFERS is on, so its storage binding
// (capped at maxStorageBufferRange) is never read past its end.

// Primitive kinds the scene has (bit k: kind k of shared/primitive_kinds.h).
#ifdef PRISM_PLANES_ONLY
// The module for tiles that see only planes (render/traced_tiles.h, tileClasses): kinds, grid
// and resumption fixed rather than specialized, so that the grid's code folds away before
// lavapipe front-ends the module (its pipeline is made in a third of the full one's time).
const uint KINDS = 1u << kKindPlane;
#else
layout(constant_id = kSpecKinds) const uint KINDS = 0xFFu;
#endif
const bool HAS_SPHERES = (KINDS & (1u << kKindSphere)) != 0u;
const bool HAS_PLANES = (KINDS & (1u << kKindPlane)) != 0u;
const bool HAS_TRIANGLES = (KINDS & (1u << kKindTriangle)) != 0u;
const bool HAS_INSTANCES = (KINDS & (1u << kKindInstance)) != 0u;
layout(constant_id = kSpecHasReflection) const bool HAS_REFLECTION = true;
layout(constant_id = kSpecHasTransmission) const bool HAS_TRANSMISSION = true;
layout(constant_id = kSpecHasTextures) const bool HAS_TEXTURES = true;
layout(constant_id = kSpecHasAreaLights) const bool HAS_AREA_LIGHTS = true;
layout(constant_id = kSpecHasVertexNormals) const bool HAS_VERTEX_NORMALS = true;
layout(constant_id = kSpecHasShadows) const bool HAS_SHADOWS = true;
layout(constant_id = kSpecHasEnvironment) const bool HAS_ENVIRONMENT = false;
layout(constant_id = kSpecHasSurfaceMaps) const bool HAS_SURFACE_MAPS = false;
layout(constant_id = kSpecWriteAov) const bool WRITE_AOV = false;
layout(constant_id = kSpecStackSize) const uint STACK_SIZE = 9u;
// Read the arrays that have texel views through them instead of storage buffers (faster on
// lavapipe, and not capped at maxStorageBufferRange; docs/benchmarks.md).
layout(constant_id = kSpecTexelBuffers) const bool TEXEL_BUFFERS = false;
#ifdef PRISM_PLANES_ONLY
const bool ADAPTIVE_GRID = false;
const bool CELL_TRIANGLES = false;
const bool CELL_SPHERES = false;
#else
layout(constant_id = kSpecAdaptiveGrid) const bool ADAPTIVE_GRID = false;
// The grid's cells list triangles only, and the cell triangle array holds each entry's triangle
// (on an adaptive grid, in cell records): a test reads its vertices by the entry, with no
// primitive id (render/tracer_features.h).
layout(constant_id = kSpecCellTriangles) const bool CELL_TRIANGLES = false;
// Likewise for a grid of spheres only: cellSphereArray holds each entry's centre and radius.
layout(constant_id = kSpecCellSpheres) const bool CELL_SPHERES = false;
#endif
// The studies' stand-ins for methods Prism replaced (trace_interface.h); the defaults fold away.
layout(constant_id = kSpecFixedRayOffset) const float FIXED_RAY_OFFSET = 0.0;
layout(constant_id = kSpecTriangleTest) const uint TRIANGLE_TEST = kTriangleTestWatertight;
const bool MOLLER_TRUMBORE = TRIANGLE_TEST == kTriangleTestMollerTrumbore;
#ifdef PRISM_PLANES_ONLY
const bool RESUMABLE = false;
#else
layout(constant_id = kSpecResumable) const bool RESUMABLE = false;
#endif

layout(set = 0, binding = kBindingAccumImage, rgba32f) uniform image2D accumImage;
layout(set = 0, binding = kBindingAovImage, rgba32f) uniform writeonly image2D aovImage;
layout(std430, set = 0, binding = kBindingStats) buffer StatsBuffer { GpuStats stats; };
layout(std430, set = 0, binding = kBindingResumeRecords) buffer ResumeRecordBuffer {
    GpuResumeRecord resumeRecords[];
};
layout(std430, set = 0, binding = kBindingWalkLog) buffer WalkLogBuffer { uvec4 walkLog[]; };
// The header is a uniform buffer: lavapipe reads a uniform block at a uniform offset with one
// scalar load, where a storage buffer costs a loop over the 8 lanes, each with a bounds check,
// at every read (and the walk reads the header at every step and test). std140 and std430
// agree on GpuSceneHeader: it has only 16-byte vectors.
layout(std140, set = 0, binding = kBindingHeader) uniform HeaderBlock {
    GpuSceneHeader header;
};
layout(std430, set = 0, binding = kBindingSpheres) readonly buffer SphereBuffer {
    GpuSphere sphereArray[];
};
layout(std430, set = 0, binding = kBindingPlanes) readonly buffer PlaneBuffer {
    GpuPlane planeArray[];
};
layout(std430, set = 0, binding = kBindingTriangles) readonly buffer TriangleBuffer {
    GpuTriangle triangleArray[];
};
layout(std430, set = 0, binding = kBindingTriangleShading) readonly buffer ShadingBuffer {
    GpuTriangleShading shadingArray[];
};
layout(std430, set = 0, binding = kBindingMaterials) readonly buffer MaterialBuffer {
    GpuMaterial materialArray[];
};
layout(std430, set = 0, binding = kBindingLights) readonly buffer LightBuffer {
    GpuLight lightArray[];
};
layout(std430, set = 0, binding = kBindingCellStart) readonly buffer CellStartBuffer {
    uint cellStartArray[];
};
layout(std430, set = 0, binding = kBindingCellPrimitives) readonly buffer CellPrimitiveBuffer {
    uint cellPrimitiveArray[];
};
layout(std430, set = 0, binding = kBindingTextures) readonly buffer TextureBuffer {
    GpuTexture textureArray[];
};
layout(std430, set = 0, binding = kBindingTexels) readonly buffer TexelBuffer {
    vec4 texelArray[];
};
layout(std430, set = 0, binding = kBindingGridEntries) readonly buffer GridEntryBuffer {
    uint gridEntryArray[];
};
layout(std430, set = 0, binding = kBindingCellBoxes) readonly buffer CellBoxBuffer {
    uvec4 cellBoxArray[];
};
layout(std430, set = 0, binding = kBindingInstances) readonly buffer InstanceBuffer {
    GpuInstance instanceArray[];
};
layout(std430, set = 0, binding = kBindingMeshGrids) readonly buffer MeshGridBuffer {
    GpuMeshGrid meshGridArray[];
};
// Rows of 16 bytes: three per GpuCellTriangle, and on an adaptive grid the cell records'
// box rows between them (gpu_types.h, cellRecordRow).
layout(std430, set = 0, binding = kBindingCellTriangles) readonly buffer CellTriangleBuffer {
    uvec4 cellTriangleRowArray[];
};
layout(std430, set = 0, binding = kBindingCellSpheres) readonly buffer CellSphereBuffer {
    vec4 cellSphereArray[];
};
layout(set = 0, binding = kBindingCellStartTexels) uniform usamplerBuffer cellStartTexels;
layout(set = 0, binding = kBindingCellPrimitiveTexels) uniform usamplerBuffer cellPrimitiveTexels;
layout(set = 0, binding = kBindingSphereTexels) uniform samplerBuffer sphereTexels;
layout(set = 0, binding = kBindingTriangleTexels) uniform samplerBuffer triangleTexels;
layout(set = 0, binding = kBindingImageTexels) uniform samplerBuffer imageTexels;
layout(set = 0, binding = kBindingTriangleShadingTexels) uniform samplerBuffer shadingTexels;
layout(set = 0, binding = kBindingGridEntryTexels) uniform usamplerBuffer gridEntryTexels;
layout(set = 0, binding = kBindingCellBoxTexels) uniform usamplerBuffer cellBoxTexels;
layout(set = 0, binding = kBindingInstanceTexels) uniform samplerBuffer instanceTexels;
layout(set = 0, binding = kBindingPlaneTexels) uniform samplerBuffer planeTexels;
layout(set = 0, binding = kBindingMaterialTexels) uniform samplerBuffer materialTexels;
layout(set = 0, binding = kBindingLightTexels) uniform samplerBuffer lightTexels;
layout(set = 0, binding = kBindingMeshGridTexels) uniform usamplerBuffer meshGridTexels;
layout(set = 0, binding = kBindingTextureTexels) uniform usamplerBuffer textureInfoTexels;
layout(set = 0, binding = kBindingCellTriangleTexels) uniform usamplerBuffer cellTriangleTexels;
layout(set = 0, binding = kBindingTileList) uniform usamplerBuffer tileListTexels;
layout(set = 0, binding = kBindingCellSphereTexels) uniform samplerBuffer cellSphereTexels;

layout(push_constant) uniform FrameBlock { GpuFrameParams frame; };

// Arrays with texel views: through whichever binding TEXEL_BUFFERS selects.
uint cellStartAt(uint i) {
    return TEXEL_BUFFERS ? texelFetch(cellStartTexels, int(i)).x : cellStartArray[i];
}
uint cellPrimitiveAt(uint k) {
    return TEXEL_BUFFERS ? texelFetch(cellPrimitiveTexels, int(k)).x : cellPrimitiveArray[k];
}
// Entry i of the frame's tile list: the tile's first pixel, and the distance along its camera
// rays before which they meet nothing in the grid (render/traced_tiles.h, tileStartDistances).
uvec2 tileListOrigin(uvec2 entry) {
    return uvec2(entry.x & 0xFFFFu, entry.x >> 16u) * 8u;
}
float tileListStart(uvec2 entry) {
    return uintBitsToFloat(entry.y);
}
uvec2 tileListEntry(uint i) {
    return texelFetch(tileListTexels, int(i)).xy;
}
// Row i of the cell triangle array.
uvec4 cellTriangleRowAt(uint i) {
    return TEXEL_BUFFERS ? texelFetch(cellTriangleTexels, int(i)) : cellTriangleRowArray[i];
}
// Cell entry k's sphere: xyz centre, w radius.
vec4 cellSphereAt(uint k) {
    return TEXEL_BUFFERS ? texelFetch(cellSphereTexels, int(k)) : cellSphereArray[k];
}
uint gridEntryAt(uint i) {
    return TEXEL_BUFFERS ? texelFetch(gridEntryTexels, int(i)).x : gridEntryArray[i];
}
uvec4 cellBoxAt(uint i) {
    return TEXEL_BUFFERS ? texelFetch(cellBoxTexels, int(i)) : cellBoxArray[i];
}
vec4 sphereCenterRadius(uint i) { // the intersection loop needs only this half
    return TEXEL_BUFFERS ? texelFetch(sphereTexels, int(2u * i)) : sphereArray[i].centerRadius;
}
GpuSphere sphereAt(uint i) {
    if (TEXEL_BUFFERS)
        return GpuSphere(texelFetch(sphereTexels, int(2u * i)),
                         texelFetch(sphereTexels, int(2u * i + 1u)));
    return sphereArray[i];
}
vec3 triangleVertex(uint tri, uint corner) {
    if (TEXEL_BUFFERS)
        return texelFetch(triangleTexels, int(3u * tri + corner)).xyz;
    return corner == 0u ? triangleArray[tri].v0.xyz
                        : (corner == 1u ? triangleArray[tri].v1.xyz : triangleArray[tri].v2.xyz);
}
GpuTriangle triangleAt(uint i) {
    if (TEXEL_BUFFERS)
        return GpuTriangle(texelFetch(triangleTexels, int(3u * i)),
                           texelFetch(triangleTexels, int(3u * i + 1u)),
                           texelFetch(triangleTexels, int(3u * i + 2u)));
    return triangleArray[i];
}
GpuTriangleShading triangleShadingAt(uint i) {
    if (TEXEL_BUFFERS)
        return GpuTriangleShading(
            texelFetch(shadingTexels, int(5u * i)), texelFetch(shadingTexels, int(5u * i + 1u)),
            texelFetch(shadingTexels, int(5u * i + 2u)), texelFetch(shadingTexels, int(5u * i + 3u)),
            texelFetch(shadingTexels, int(5u * i + 4u)));
    return shadingArray[i];
}
// An instance's way into its prototype's space (rows 0-2) and its info; the way out (rows 3-5)
// only shading needs.
vec4 instanceRow(uint i, uint row) {
    if (TEXEL_BUFFERS)
        return texelFetch(instanceTexels, int(7u * i + row));
    GpuInstance g = instanceArray[i];
    return row == 0u ? g.toObject0 : row == 1u ? g.toObject1 : row == 2u ? g.toObject2
         : row == 3u ? g.toWorld0 : row == 4u ? g.toWorld1 : row == 5u ? g.toWorld2 : g.info;
}
vec4 textureTexel(uint i) {
    return TEXEL_BUFFERS ? texelFetch(imageTexels, int(i)) : texelArray[i];
}

// The small arrays: one element per plane, material, light, prototype and texture.
vec4 planeEquation(uint i) { // xyz unit normal, w offset: all the intersection loop needs
    return TEXEL_BUFFERS ? texelFetch(planeTexels, int(2u * i)) : planeArray[i].normalOffset;
}
GpuPlane planeAt(uint i) {
    if (TEXEL_BUFFERS)
        return GpuPlane(texelFetch(planeTexels, int(2u * i)),
                        texelFetch(planeTexels, int(2u * i + 1u)));
    return planeArray[i];
}
GpuMaterial materialAt(uint i) {
    if (TEXEL_BUFFERS)
        return GpuMaterial(
            texelFetch(materialTexels, int(4u * i)), texelFetch(materialTexels, int(4u * i + 1u)),
            texelFetch(materialTexels, int(4u * i + 2u)),
            texelFetch(materialTexels, int(4u * i + 3u)));
    return materialArray[i];
}
GpuLight lightAt(uint i) {
    if (TEXEL_BUFFERS)
        return GpuLight(texelFetch(lightTexels, int(2u * i)),
                        texelFetch(lightTexels, int(2u * i + 1u)));
    return lightArray[i];
}
GpuMeshGrid meshGridAt(uint i) {
    if (TEXEL_BUFFERS)
        return GpuMeshGrid(uintBitsToFloat(texelFetch(meshGridTexels, int(4u * i))),
                           uintBitsToFloat(texelFetch(meshGridTexels, int(4u * i + 1u))),
                           uintBitsToFloat(texelFetch(meshGridTexels, int(4u * i + 2u))),
                           texelFetch(meshGridTexels, int(4u * i + 3u)));
    return meshGridArray[i];
}
GpuTexture textureAt(uint i) {
    if (TEXEL_BUFFERS) // not a ?: (glslang stores a block's struct into a local of another type)
        return GpuTexture(texelFetch(textureInfoTexels, int(i)));
    return textureArray[i];
}
