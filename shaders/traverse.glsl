// Finding what a ray hits: infinite planes by brute force, everything else through the regular
// grid with 3D-DDA (Amanatides & Woo 1987). One walk (trace_ray.glsl) serves both closest-hit
// rays and any-hit (shadow) rays.

struct Hit {
    float t;
    uint kind;  // kKindSphere, kKindTriangle, kKindPlane or kKindNone
    uint index; // within its kind's array
    vec2 b12;   // triangle barycentrics of p1 and p2
};

// Tests the primitive with grid id `id` and records it in `hit` when closer than hit.t.
void testPrimitive(uint id, vec3 origin, vec3 dir, WatertightRay wray, inout Hit hit) {
    float t;
    if (HAS_SPHERES && id < header.idEnd[kKindSphere]) {
        uint sphere = id; // the first kind: its ids start at 0
        if (intersectSphere(origin, dir, sphereCenterRadius(sphere), hit.t, t)) {
            hit.t = t;
            hit.kind = kKindSphere;
            hit.index = sphere;
        }
    } else if (HAS_TRIANGLES) { // the last kind: every id past the spheres
        // primitiveIdFirst(header.idEnd, kKindTriangle), written with a constant index: lavapipe
        // then loads one word, not the whole idEnd vector, per test (that cost 7% on objects).
        uint tri = id - header.idEnd[kKindTriangle - 1u];
        vec2 b12;
        if (intersectTriangle(origin, wray, triangleVertex(tri, 0u), triangleVertex(tri, 1u),
                              triangleVertex(tri, 2u), hit.t, t, b12)) {
            hit.t = t;
            hit.kind = kKindTriangle;
            hit.index = tri;
            hit.b12 = b12;
        }
    }
}

// Slab test against the grid's box; returns the parametric range inside it.
bool clipToGrid(vec3 origin, vec3 invDir, out float tEnter, out float tExit) {
    vec3 t0 = (header.gridMin.xyz - origin) * invDir;
    vec3 t1 = (header.gridMax.xyz - origin) * invDir;
    vec3 tNear = min(t0, t1), tFar = max(t0, t1);
    tEnter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    tExit = min(min(tFar.x, tFar.y), tFar.z);
    return tEnter <= tExit;
}

// The DDA walker's state: current cell, parametric distance to the next cell face per axis.
struct GridWalk {
    ivec3 cell;
    ivec3 step;
    vec3 tNext;
    vec3 tDelta;
};

GridWalk startWalk(vec3 origin, vec3 dir, vec3 invDir, float tEnter) {
    GridWalk w;
    ivec3 res = ivec3(header.gridRes.xyz);
    vec3 entry = origin + tEnter * dir;
    w.cell = clamp(ivec3(floor((entry - header.gridMin.xyz) / header.cellSize.xyz)), ivec3(0),
                   res - 1);
    w.step = ivec3(sign(dir));
    vec3 nextFace = header.gridMin.xyz + (vec3(w.cell) + max(vec3(w.step), vec3(0.0))) *
                                             header.cellSize.xyz;
    w.tNext = mix((nextFace - origin) * invDir, vec3(kInfinity), equal(w.step, ivec3(0)));
    w.tDelta = mix(header.cellSize.xyz * abs(invDir), vec3(kInfinity), equal(w.step, ivec3(0)));
    return w;
}

// Advances to the next cell; false when the ray leaves the grid.
bool stepWalk(inout GridWalk w) {
    int axis = w.tNext.x < w.tNext.y ? (w.tNext.x < w.tNext.z ? 0 : 2)
                                     : (w.tNext.y < w.tNext.z ? 1 : 2);
    w.cell[axis] += w.step[axis];
    w.tNext[axis] += w.tDelta[axis];
    return w.cell[axis] >= 0 && w.cell[axis] < int(header.gridRes[axis]);
}

uint cellIndex(ivec3 cell) {
    return uint(cell.x) + header.gridRes.x * (uint(cell.y) + header.gridRes.y * uint(cell.z));
}

// One walk for both kinds of query (trace_ray.glsl), planes first, then the grid.
#define TRACE_RAY_NAME traceClosest
#define TRACE_RAY_ANY_HIT 0
#include "trace_ray.glsl"
#undef TRACE_RAY_NAME
#undef TRACE_RAY_ANY_HIT
#define TRACE_RAY_NAME traceAnyHit
#define TRACE_RAY_ANY_HIT 1
#include "trace_ray.glsl"
#undef TRACE_RAY_NAME
#undef TRACE_RAY_ANY_HIT

// True when anything lies on the open segment 0 < t < tMax.
bool traceOccluded(vec3 origin, vec3 dir, float tMax) {
    Hit hit;
    return traceAnyHit(origin, dir, tMax, hit);
}
