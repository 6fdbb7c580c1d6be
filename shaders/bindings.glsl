// Descriptor bindings and specialization constants of the tracer (trace.comp). The host side is
// engine/render/tracer_bindings.h; keep the two in step.

// Features a scene does not use are compiled out (constant_id order = TracerSpecialization).
layout(constant_id = 0) const bool HAS_SPHERES = true;
layout(constant_id = 1) const bool HAS_PLANES = true;
layout(constant_id = 2) const bool HAS_TRIANGLES = true;
layout(constant_id = 3) const bool HAS_REFLECTION = true;
layout(constant_id = 4) const bool HAS_TRANSMISSION = true;
layout(constant_id = 5) const bool HAS_TEXTURES = true;
layout(constant_id = 6) const bool HAS_AREA_LIGHTS = true;
layout(constant_id = 7) const bool HAS_VERTEX_NORMALS = true;
layout(constant_id = 8) const bool HAS_SHADOWS = true;
layout(constant_id = 9) const bool WRITE_AOV = false;
// Loop iterations one invocation may run (0: unlimited). lavapipe stops any invocation after
// 65,535 loop iterations without telling anyone; we stop first and report it.
layout(constant_id = 10) const uint LOOP_BUDGET = 0u;
layout(constant_id = 11) const uint STACK_SIZE = 9u; // 2 * maxDepth - 1
// Read the hot arrays (cells, spheres, triangle vertices) through uniform texel buffers instead
// of storage buffers; the host binds the same buffers both ways (docs/benchmarks.md).
layout(constant_id = 12) const bool TEXEL_BUFFERS = false;

layout(set = 0, binding = 0, rgba32f) uniform image2D accumImage;     // sum of sample radiance
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D aovImage; // xyz normal, w depth
layout(std430, set = 0, binding = 2) readonly buffer HeaderBuffer { GpuSceneHeader header; };
layout(std430, set = 0, binding = 3) readonly buffer SphereBuffer { GpuSphere spheres[]; };
layout(std430, set = 0, binding = 4) readonly buffer PlaneBuffer { GpuPlane planes[]; };
layout(std430, set = 0, binding = 5) readonly buffer TriangleBuffer { GpuTriangle triangles[]; };
layout(std430, set = 0, binding = 6) readonly buffer ShadingBuffer { GpuTriangleShading triangleShading[]; };
layout(std430, set = 0, binding = 7) readonly buffer MaterialBuffer { GpuMaterial materials[]; };
layout(std430, set = 0, binding = 8) readonly buffer LightBuffer { GpuLight lights[]; };
layout(std430, set = 0, binding = 9) readonly buffer CellStartBuffer { uint cellStart[]; };
layout(std430, set = 0, binding = 10) readonly buffer CellPrimitiveBuffer { uint cellPrimitives[]; };
layout(std430, set = 0, binding = 11) readonly buffer TextureBuffer { GpuTexture textures[]; };
layout(std430, set = 0, binding = 12) readonly buffer TexelBuffer { vec4 texels[]; };
layout(set = 0, binding = 14) uniform usamplerBuffer cellStartTexels;
layout(set = 0, binding = 15) uniform usamplerBuffer cellPrimitiveTexels;
layout(set = 0, binding = 16) uniform samplerBuffer sphereTexels;   // 2 texels per GpuSphere
layout(set = 0, binding = 17) uniform samplerBuffer triangleTexels; // 3 texels per GpuTriangle
layout(set = 0, binding = 18) uniform samplerBuffer imageTexels;    // the texture texels
// GpuStats viewed as 64-bit counters: 0 primary, 2 shadow, 4 secondary, 6 over-budget pixels.
layout(std430, set = 0, binding = 13) buffer StatsBuffer { uint64_t counters[8]; };

layout(push_constant) uniform FrameBlock { GpuFrameParams frame; };

// The traversal's reads, through whichever binding TEXEL_BUFFERS selects.
uint cellStartAt(uint i) {
    return TEXEL_BUFFERS ? texelFetch(cellStartTexels, int(i)).x : cellStart[i];
}
uint cellPrimitiveAt(uint k) {
    return TEXEL_BUFFERS ? texelFetch(cellPrimitiveTexels, int(k)).x : cellPrimitives[k];
}
vec4 sphereCenterRadius(uint i) {
    return TEXEL_BUFFERS ? texelFetch(sphereTexels, int(2u * i)) : spheres[i].centerRadius;
}
vec3 triangleVertex(uint tri, uint corner) {
    if (TEXEL_BUFFERS)
        return texelFetch(triangleTexels, int(3u * tri + corner)).xyz;
    return corner == 0u ? triangles[tri].v0.xyz
                        : (corner == 1u ? triangles[tri].v1.xyz : triangles[tri].v2.xyz);
}
vec4 textureTexel(uint i) {
    return TEXEL_BUFFERS ? texelFetch(imageTexels, int(i)) : texels[i];
}
