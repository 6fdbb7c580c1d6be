// Finding what a ray hits: infinite planes by brute force, everything else through the regular
// grid with 3D-DDA (Amanatides & Woo 1987).

const uint kHitSphere = 0u, kHitPlane = 1u, kHitTriangle = 2u;

struct Hit {
    float t;
    uint kind;
    uint index;
    vec2 b12; // triangle barycentrics of p1 and p2
};

// Tests primitive `id` (grid id space) and records it in `hit` when closer than hit.t.
void testPrimitive(uint id, vec3 origin, vec3 dir, WatertightRay wray, inout Hit hit) {
    float t;
    uint sphereCount = header.counts.x;
    if (HAS_SPHERES && id < sphereCount) {
        if (intersectSphere(origin, dir, sphereCenterRadius(id), hit.t, t)) {
            hit.t = t;
            hit.kind = kHitSphere;
            hit.index = id;
        }
    } else if (HAS_TRIANGLES) {
        uint tri = id - sphereCount;
        vec2 b12;
        if (intersectTriangle(origin, wray, triangleVertex(tri, 0u), triangleVertex(tri, 1u),
                              triangleVertex(tri, 2u), hit.t, t, b12)) {
            hit.t = t;
            hit.kind = kHitTriangle;
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

// Closest hit with 0 < t < tMax. A grid hit is accepted only once the walk has reached the
// cell where it lies (t <= the cell's exit), so the first accepted hit is the nearest.
bool traceClosest(vec3 origin, vec3 dir, float tMax, out Hit hit) {
    hit.t = tMax;
    hit.kind = 0xFFFFFFFFu;
    hit.index = 0u;
    hit.b12 = vec2(0.0);
    if (HAS_PLANES) {
        for (uint i = 0u; i < header.counts.y; ++i) {
            if (!loopTick()) break;
            float t;
            if (intersectPlane(origin, dir, planes[i].normalOffset, hit.t, t)) {
                hit.t = t;
                hit.kind = kHitPlane;
                hit.index = i;
            }
        }
    }
    if (HAS_SPHERES || HAS_TRIANGLES) {
        vec3 invDir = 1.0 / dir;
        float tEnter, tExit;
        if (clipToGrid(origin, invDir, tEnter, tExit) && tEnter < hit.t) {
            WatertightRay wray = makeWatertightRay(dir);
            GridWalk walk = startWalk(origin, dir, invDir, tEnter);
            bool walking = true;
            while (walking) {
                if (!loopTick()) break;
                float tCellExit = min(min(walk.tNext.x, walk.tNext.y), walk.tNext.z);
                uint cell = cellIndex(walk.cell);
                uint end = cellStartAt(cell + 1u);
                for (uint k = cellStartAt(cell); k < end; ++k) {
                    if (!loopTick()) break;
                    testPrimitive(cellPrimitiveAt(k), origin, dir, wray, hit);
                }
                // Stop once the best hit lies in this cell (or a plane hit comes first).
                walking = hit.t > tCellExit && tCellExit < tExit && stepWalk(walk) &&
                          !gOverBudget;
                loopSync();
            }
            loopSync();
        }
    }
    return hit.kind != 0xFFFFFFFFu;
}

// True when anything lies on the open segment 0 < t < tMax (shadow rays: any hit will do).
bool traceOccluded(vec3 origin, vec3 dir, float tMax) {
    Hit hit;
    hit.t = tMax;
    hit.kind = 0xFFFFFFFFu;
    if (HAS_PLANES) {
        for (uint i = 0u; i < header.counts.y; ++i) {
            if (!loopTick()) break;
            float t;
            if (intersectPlane(origin, dir, planes[i].normalOffset, tMax, t))
                return true;
        }
    }
    if (HAS_SPHERES || HAS_TRIANGLES) {
        vec3 invDir = 1.0 / dir;
        float tEnter, tExit;
        if (clipToGrid(origin, invDir, tEnter, tExit) && tEnter < tMax) {
            WatertightRay wray = makeWatertightRay(dir);
            GridWalk walk = startWalk(origin, dir, invDir, tEnter);
            bool walking = true;
            while (walking) {
                if (!loopTick()) break;
                float tCellExit = min(min(walk.tNext.x, walk.tNext.y), walk.tNext.z);
                uint cell = cellIndex(walk.cell);
                uint end = cellStartAt(cell + 1u);
                for (uint k = cellStartAt(cell); k < end && hit.kind == 0xFFFFFFFFu; ++k) {
                    if (!loopTick()) break;
                    testPrimitive(cellPrimitiveAt(k), origin, dir, wray, hit);
                }
                walking = hit.kind == 0xFFFFFFFFu && tCellExit < min(tExit, tMax) &&
                          stepWalk(walk) && !gOverBudget;
                loopSync();
            }
            loopSync();
        }
    }
    return hit.kind != 0xFFFFFFFFu;
}
