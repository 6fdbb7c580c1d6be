// Buffer layouts shared by the host (C++) and the tracer (GLSL), std430. Every member is a
// vec4/uvec4 so the two agree without padding rules; the static_asserts below pin them down.
#ifndef PRISM_GPU_TYPES_H
#define PRISM_GPU_TYPES_H
#include "glsl_compat.h"

PRISM_NAMESPACE_BEGIN

// Secondary/shadow ray origins move off the surface by this fraction of max|P_i| (2^-18: some
// 32 float ulps, above the few ulps of error in a rebuilt hit point), so a scene behaves the
// same at any scale and distance from the origin. The CPU reference uses the same number.
#define PRISM_OFFSET_RELATIVE 3.814697265625e-06
#define PRISM_OFFSET_FLOOR 1e-30

// Primitive ids in grid cells: spheres [0, sphereCount), then triangles.
struct GpuSceneHeader {
    vec4 gridMin;    // xyz: grid bounds min
    vec4 gridMax;    // xyz: grid bounds max
    vec4 cellSize;   // xyz: size of one cell; w unused
    uvec4 gridRes;   // xyz: cells per axis; w: cell count
    uvec4 counts;    // x: spheres, y: planes, z: triangles, w: lights
    vec4 background; // rgb
    vec4 ambient;    // rgb: scene ambient light
};

struct GpuSphere {
    vec4 centerRadius; // xyz centre, w radius
    uvec4 material;    // x: material index
};

struct GpuPlane {
    vec4 normalOffset; // xyz unit normal, w = dot(normal, point)
    vec4 point;        // xyz a point on the plane; w: material index (as float, exact)
};

// Vertices only: the intersection loop reads 48 bytes per triangle; shading data lives apart.
struct GpuTriangle {
    vec4 v0; // w: material index (as float, exact below 2^24)
    vec4 v1;
    vec4 v2;
};

struct GpuTriangleShading {
    vec4 n0; // vertex normals; n0.w = 1 when present
    vec4 n1; // n1.w = 1 when texture coordinates are present
    vec4 n2;
    vec4 uv01; // xy: uv0, zw: uv1
    vec4 uv2;  // xy: uv2
};

struct GpuMaterial {
    vec4 colorAmbient; // rgb colour, a: ambient coefficient
    vec4 lighting;     // x diffuse, y specular, z shininess, w reflect
    vec4 optics;       // x transmit, y ior, z texture index (-1: none)
};

struct GpuLight {
    vec4 positionRadius; // xyz position, w radius (0: point light)
    vec4 color;
};

struct GpuTexture {
    uvec4 info; // x: first texel in the texel array, y: width, z: height
};

// Counters the tracer adds to with atomics (64-bit: a frame can trace billions of rays).
struct GpuStats {
    uvec4 primary; // xy: uint64 as two words (lo, hi)
    uvec4 shadow;
    uvec4 secondary;
    uvec4 budget; // x: pixels that hit the loop budget
};

// Per-frame parameters (push constants, 128 bytes at most).
struct GpuFrameParams {
    vec4 eye;      // xyz: camera position; w: 1 for parallel projection
    vec4 forward;  // xyz: unit view direction
    vec4 du;       // right scaled by h*a (perspective) or (H/2)*a (ortho)
    vec4 dv;       // true up scaled by h (perspective) or H/2 (ortho)
    uvec4 image;   // x width, y height, z first sample index, w samples per pixel in total
    uvec4 control; // x: max depth, y: samples in this dispatch
};

PRISM_NAMESPACE_END

#ifdef __cplusplus
#include <cstddef>
namespace prism::gpu {
static_assert(sizeof(GpuSceneHeader) == 112);
static_assert(offsetof(GpuSceneHeader, gridRes) == 48);
static_assert(offsetof(GpuSceneHeader, ambient) == 96);
static_assert(sizeof(GpuSphere) == 32);
static_assert(sizeof(GpuPlane) == 32);
static_assert(sizeof(GpuTriangle) == 48);
static_assert(sizeof(GpuTriangleShading) == 80);
static_assert(offsetof(GpuTriangleShading, uv01) == 48);
static_assert(sizeof(GpuMaterial) == 48);
static_assert(offsetof(GpuMaterial, optics) == 32);
static_assert(sizeof(GpuLight) == 32);
static_assert(sizeof(GpuTexture) == 16);
static_assert(sizeof(GpuStats) == 64);
static_assert(sizeof(GpuFrameParams) == 96);
static_assert(offsetof(GpuFrameParams, image) == 64);
static_assert(sizeof(GpuFrameParams) <= 128, "push constants are limited to 128 bytes");
} // namespace prism::gpu
#endif
#endif
