// Finding what a ray hits: infinite planes by brute force, everything else through the grid
// (regular, with 3D-DDA, Amanatides & Woo 1987, or adaptive). One walk (trace_ray.glsl) serves
// both closest-hit rays and any-hit (shadow) rays. An instance in the grid is a second walk: the
// ray taken into its prototype's space through the prototype's own regular grid.

struct Hit {
    float t;
    uint kind;     // kKindSphere, kKindTriangle, kKindPlane or kKindNone
    uint index;    // within its kind's array
    vec2 b12;      // triangle barycentrics of p1 and p2
    uint instance; // a triangle of a prototype: the instance it was hit in; else kNoInstance
};
const uint kNoInstance = 0xFFFFFFFFu;

// A hit nearer than hit.t becomes the hit (an instance's walk then marks its triangles).
void recordHit(inout Hit hit, float t, uint kind, uint index) {
    hit.t = t;
    hit.kind = kind;
    hit.index = index;
    hit.instance = kNoInstance;
}

#include "resume.glsl"

// Tests triangle `tri` (of the triangle array), whose vertices are p0, p1, p2, and records it in
// `hit` when closer than hit.t.
bool testTriangleAt(uint tri, vec3 p0, vec3 p1, vec3 p2, vec3 origin, vec3 dir,
                    WatertightRay wray, inout Hit hit) {
    float t;
    vec2 b12;
    bool hitTriangle;
    if (MOLLER_TRUMBORE)
        hitTriangle = intersectTriangleMollerTrumbore(origin, dir, p0, p1, p2, hit.t, t, b12);
    else
        hitTriangle = intersectTriangle(origin, wray, p0, p1, p2, hit.t, t, b12);
    if (hitTriangle) {
        recordHit(hit, t, kKindTriangle, tri);
        hit.b12 = b12;
    }
    return hitTriangle;
}

bool testTriangle(uint tri, vec3 origin, vec3 dir, WatertightRay wray, inout Hit hit) {
    return testTriangleAt(tri, triangleVertex(tri, 0u), triangleVertex(tri, 1u),
                          triangleVertex(tri, 2u), origin, dir, wray, hit);
}

// The cell triangle (GpuCellTriangle) from row `row` of the cell triangle array (CELL_TRIANGLES):
// three texels, no primitive id to fetch first.
void testCellTriangle(uint row, vec3 origin, vec3 dir, WatertightRay wray, inout Hit hit) {
    uvec4 row0 = cellTriangleRowAt(row);
    testTriangleAt(cellTriangleIndex(row0), uintBitsToFloat(row0.xyz),
                   uintBitsToFloat(cellTriangleRowAt(row + 1u).xyz),
                   uintBitsToFloat(cellTriangleRowAt(row + 2u).xyz), origin, dir, wray, hit);
}

// The sphere of cell entry k (CELL_SPHERES): one texel, no primitive id. The hit records the
// entry, not the sphere: resolveCellHit finds the sphere once the walk is done.
void testCellSphere(uint k, vec3 origin, vec3 dir, inout Hit hit) {
    float t;
    if (intersectSphere(origin, dir, cellSphereAt(k), hit.t, t))
        recordHit(hit, t, kKindSphere, k);
}

// After a finished walk of a CELL_SPHERES grid: the sphere hit's entry becomes the sphere (a
// sphere-only grid's ids are sphere indices, scene/primitive_ids.h).
void resolveCellHit(inout Hit hit) {
    if (CELL_SPHERES && hit.kind == kKindSphere)
        hit.index = cellPrimitiveAt(hit.index);
}

// Slab test against a box; returns the parametric range inside it.
bool clipToBox(vec3 boxMin, vec3 boxMax, vec3 origin, vec3 invDir, out float tEnter,
               out float tExit) {
    vec3 t0 = (boxMin - origin) * invDir;
    vec3 t1 = (boxMax - origin) * invDir;
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

GridWalk startGridWalk(vec3 gridMin, vec3 cellSize, ivec3 res, vec3 origin, vec3 dir,
                       vec3 invDir, float tEnter) {
    GridWalk w;
    vec3 entry = origin + tEnter * dir;
    w.cell = clamp(ivec3(floor((entry - gridMin) / cellSize)), ivec3(0), res - 1);
    w.step = ivec3(sign(dir));
    vec3 nextFace = gridMin + (vec3(w.cell) + max(vec3(w.step), vec3(0.0))) * cellSize;
    w.tNext = mix((nextFace - origin) * invDir, vec3(kInfinity), equal(w.step, ivec3(0)));
    w.tDelta = mix(cellSize * abs(invDir), vec3(kInfinity), equal(w.step, ivec3(0)));
    return w;
}

// Advances to the next cell; false when the ray leaves the grid.
bool stepGridWalk(inout GridWalk w, ivec3 res) {
    int axis = w.tNext.x < w.tNext.y ? (w.tNext.x < w.tNext.z ? 0 : 2)
                                     : (w.tNext.y < w.tNext.z ? 1 : 2);
    w.cell[axis] += w.step[axis];
    w.tNext[axis] += w.tDelta[axis];
    return w.cell[axis] >= 0 && w.cell[axis] < res[axis];
}

uint gridCellIndex(ivec3 cell, uvec3 res) {
    return uint(cell.x) + res.x * (uint(cell.y) + res.y * uint(cell.z));
}

// Instance `inst`: the ray in its prototype's space, where t is the same (the placement is a
// similarity; the direction there is not unit length, which the triangle tests do not need),
// walks the prototype's regular grid. A hit is a triangle hit of this instance. With anyHit the
// walk stops at the first.
//
// The walk covers only the part of the ray in the scene grid's current cell (tCellEnter to
// tCellExit): an instance spans several cells, and is listed in each, so a ray meets it once per
// cell; walking all of it each time would repeat the same cells. No hit is lost: a hit lies in
// some scene cell, whose visit walks the prototype's cells there; hits found past the cell are
// kept (as any test's are) and accepted once the scene walk gets there.
void testInstance(uint inst, vec3 origin, vec3 dir, bool anyHit, float tCellEnter,
                  float tCellExit, inout Hit hit) {
    vec4 r0 = instanceRow(inst, 0u), r1 = instanceRow(inst, 1u), r2 = instanceRow(inst, 2u);
    vec3 o = vec3(dot(r0.xyz, origin) + r0.w, dot(r1.xyz, origin) + r1.w,
                  dot(r2.xyz, origin) + r2.w);
    vec3 d = vec3(dot(r0.xyz, dir), dot(r1.xyz, dir), dot(r2.xyz, dir));
    GpuMeshGrid grid = meshGridAt(instancePrototype(instanceRow(inst, 6u)));
    vec3 invD = 1.0 / d;
    float tEnter, tExit;
    bool crosses = clipToBox(grid.gridMin.xyz, grid.gridMax.xyz, o, invD, tEnter, tExit);
    tEnter = max(tEnter, tCellEnter);
    tExit = min(tExit, tCellExit);
    if (!crosses || tEnter > tExit || tEnter >= hit.t)
        return;
    WatertightRay wray = makeWatertightRay(d);
    ivec3 res = ivec3(grid.res.xyz);
    GridWalk walk = startGridWalk(grid.gridMin.xyz, grid.cellSize.xyz, res, o, d, invD, tEnter);
    uint firstCell = meshGridFirstCell(grid), cells = 0u, tests = 0u;
    bool walking = true;
    while (walking) {
        float tCellExit = min(min(walk.tNext.x, walk.tNext.y), walk.tNext.z);
        uint cell = firstCell + gridCellIndex(walk.cell, grid.res.xyz);
        uint first = cellStartAt(cell), end = cellStartAt(cell + 1u);
        bool found = false;
        for (uint k = first; k < end && !(anyHit && found); ++k) {
            if (testTriangle(cellPrimitiveAt(k), o, d, wray, hit)) {
                hit.instance = inst;
                found = true;
            }
        }
        ++cells;
        tests += end - first;
        // As in the scene's grid: a hit counts once the walk has reached its cell.
        walking = (anyHit ? !found : hit.t > tCellExit) && tCellExit < tExit &&
                  stepGridWalk(walk, res);
    }
    chargeBudget(8u + 4u * cells + tests); // as trace_ray.glsl charges the scene's cells
}

// Tests the primitive with grid id `id` and records it in `hit` when closer than hit.t.
// The scene grid's current cell spans tCellEnter to tCellExit of the ray (an instance's walk
// needs it).
void testPrimitive(uint id, vec3 origin, vec3 dir, WatertightRay wray, bool anyHit,
                   float tCellEnter, float tCellExit, inout Hit hit) {
    float t;
    if (HAS_SPHERES && id < header.idEnd[kKindSphere]) {
        uint sphere = id; // the first kind: its ids start at 0
        if (intersectSphere(origin, dir, sphereCenterRadius(sphere), hit.t, t))
            recordHit(hit, t, kKindSphere, sphere);
    } else if (HAS_TRIANGLES && (!HAS_INSTANCES || id < header.idEnd[kKindTriangle])) {
        // primitiveIdFirst(header.idEnd, kKindTriangle), written with a constant index: lavapipe
        // then loads one word, not the whole idEnd vector, per test (that cost 7% on objects).
        testTriangle(id - header.idEnd[kKindTriangle - 1u], origin, dir, wray, hit);
    } else if (HAS_INSTANCES) { // the last kind
        testInstance(id - header.idEnd[kKindInstance - 1u], origin, dir, anyHit, tCellEnter,
                     tCellExit, hit);
    }
}

// The scene's grid: its box, and its DDA when it is regular.
bool clipToGrid(vec3 origin, vec3 invDir, out float tEnter, out float tExit) {
    return clipToBox(header.gridMin.xyz, header.gridMax.xyz, origin, invDir, tEnter, tExit);
}

GridWalk startWalk(vec3 origin, vec3 dir, vec3 invDir, float tEnter) {
    return startGridWalk(header.gridMin.xyz, header.cellSize.xyz, ivec3(header.gridRes.xyz),
                         origin, dir, invDir, tEnter);
}

bool stepWalk(inout GridWalk w) {
    return stepGridWalk(w, ivec3(header.gridRes.xyz));
}

uint cellIndex(ivec3 cell) {
    return gridCellIndex(cell, header.gridRes.xyz);
}

// The adaptive grid's cell that holds voxel v: down the voxel map from v's top cell.
uint adaptiveCellAt(ivec3 v) {
    int shift = int(header.voxels.w);
    uint entry = gridEntryAt(cellIndex(v >> shift));
    while (entrySplit(entry) != 0u) {
        int split = int(entrySplit(entry));
        shift -= split;
        ivec3 part = (v >> shift) & ((1 << split) - 1);
        entry = gridEntryAt(entryTarget(entry) + uint(part.x + (part.y << split) +
                                                      (part.z << (2 * split))));
    }
    return entryTarget(entry);
}

// The adaptive grid's walker: the current voxel, and of the current cell its box (in voxels),
// exit distance and exit axis.
struct BoxWalk {
    ivec3 voxel;
    ivec3 boxMin, boxMax;
    // The current cell's entries in the primitive lists; with cell records (CELL_TRIANGLES),
    // 0 to its count, its triangles following its box row.
    uint firstPrimitive, endPrimitive;
    float t; // the current cell's exit (before enterBoxCell: where the walk enters)
    int axis;
};

BoxWalk startBoxWalk(vec3 origin, vec3 dir, float tEnter) {
    BoxWalk w;
    vec3 p = (origin + tEnter * dir - header.gridMin.xyz) / header.voxelSize.xyz;
    w.voxel = clamp(ivec3(floor(p)), ivec3(0), ivec3(header.voxels.xyz) - 1);
    w.t = tEnter;
    return w;
}

// Finds the cell holding the walker's voxel and where the ray leaves its box: through the
// nearest face ahead. Returns the cell; w.t becomes its exit.
uint enterBoxCell(inout BoxWalk w, vec3 origin, vec3 dir, vec3 invDir) {
    uint cell = adaptiveCellAt(w.voxel); // with cell records: the record's box row
    uvec4 box = CELL_TRIANGLES ? cellTriangleRowAt(cell) : cellBoxAt(cell);
    w.boxMin = cellBoxMin(box);
    w.boxMax = cellBoxMax(box);
    w.firstPrimitive = CELL_TRIANGLES ? 0u : cellBoxFirstPrimitive(box);
    w.endPrimitive = CELL_TRIANGLES ? cellRecordCount(box) : cellStartAt(cell + 1u);
    vec3 face = header.gridMin.xyz +
                vec3(mix(w.boxMin, w.boxMax, greaterThan(dir, vec3(0.0)))) * header.voxelSize.xyz;
    vec3 tFace = mix((face - origin) * invDir, vec3(kInfinity), equal(dir, vec3(0.0)));
    w.axis = tFace.x < tFace.y ? (tFace.x < tFace.z ? 0 : 2) : (tFace.y < tFace.z ? 1 : 2);
    w.t = max(tFace[w.axis], w.t);
    return cell;
}

// Moves to the voxel just past the exit face, at the exit point; false when that leaves the
// grid. The other coordinates stay inside the box and never move against the ray: expanded
// boxes overlap, and where a ray passes exactly along the edge two of them share, rounding
// would otherwise send it back and forth between them for ever.
bool stepBoxWalk(inout BoxWalk w, vec3 origin, vec3 dir) {
    vec3 p = (origin + w.t * dir - header.gridMin.xyz) / header.voxelSize.xyz;
    ivec3 next = clamp(ivec3(floor(p)), w.boxMin, w.boxMax - 1);
    next = mix(min(next, w.voxel), max(next, w.voxel), greaterThan(dir, vec3(0.0)));
    next[w.axis] = dir[w.axis] > 0.0 ? w.boxMax[w.axis] : w.boxMin[w.axis] - 1;
    w.voxel = next;
    // The voxel counts copied out first: a uniform block indexed by a lane's own axis is a
    // gather on lavapipe, a local vector three selects.
    ivec3 voxels = ivec3(header.voxels.xyz);
    return next[w.axis] >= 0 && next[w.axis] < voxels[w.axis];
}

// One walk for both kinds of query (trace_ray.glsl), planes first, then the grid.
#define TRACE_RAY_NAME traceClosest
#define TRACE_WALK_NAME walkClosest
#define TRACE_RAY_ANY_HIT 0
#include "trace_ray.glsl"
#undef TRACE_RAY_NAME
#undef TRACE_WALK_NAME
#undef TRACE_RAY_ANY_HIT
#define TRACE_RAY_NAME traceAnyHit
#define TRACE_WALK_NAME walkAnyHit
#define TRACE_RAY_ANY_HIT 1
#include "trace_ray.glsl"
#undef TRACE_RAY_NAME
#undef TRACE_WALK_NAME
#undef TRACE_RAY_ANY_HIT

// True when anything lies on the open segment 0 < t < tMax.
bool traceOccluded(vec3 origin, vec3 dir, float tMax) {
    Hit hit;
    return traceAnyHit(origin, dir, 0.0, tMax, hit);
}
