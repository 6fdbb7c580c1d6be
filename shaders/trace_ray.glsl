// The grid walk, written once and compiled twice by traverse.glsl: as TRACE_RAY_NAME with
// TRACE_RAY_ANY_HIT 0 (closest hit) and 1 (any hit, for shadow rays). The mode is a preprocessor
// switch rather than a bool parameter so that each mode compiles to exactly the loop it had as
// a walker of its own; the parameter, constant at every call, measured 3% slower on lavapipe.
// Hits count on the open segment 0 < t < tMax.
bool TRACE_RAY_NAME(vec3 origin, vec3 dir, float tMax, out Hit hit) {
    hit.t = tMax;
    hit.kind = kKindNone;
    hit.index = 0u;
    hit.b12 = vec2(0.0);
    if (HAS_PLANES) {
        for (uint i = 0u; i < headerPlaneCount(header); ++i) {
            float t;
            if (intersectPlane(origin, dir, planeEquation(i), hit.t, t)) {
                hit.t = t;
                hit.kind = kKindPlane;
                hit.index = i;
#if TRACE_RAY_ANY_HIT
                return true;
#endif
            }
        }
    }
    if (HAS_SPHERES || HAS_TRIANGLES) {
        vec3 invDir = 1.0 / dir;
        float tEnter, tExit;
        if (clipToGrid(origin, invDir, tEnter, tExit) && tEnter < hit.t) {
            WatertightRay wray = makeWatertightRay(dir);
            // A regular grid is walked with 3D-DDA, an adaptive one from cell box to cell box.
            GridWalk walk;
            BoxWalk boxWalk;
            if (ADAPTIVE_GRID)
                boxWalk = startBoxWalk(origin, dir, tEnter);
            else
                walk = startWalk(origin, dir, invDir, tEnter);
            bool walking = true;
            while (walking) {
                uint cell, first;
                float tCellExit;
                if (ADAPTIVE_GRID) {
                    cell = enterBoxCell(boxWalk, origin, dir, invDir);
                    first = boxWalk.firstPrimitive;
                    tCellExit = boxWalk.t;
                } else {
                    tCellExit = min(min(walk.tNext.x, walk.tNext.y), walk.tNext.z);
                    cell = cellIndex(walk.cell);
                    first = cellStartAt(cell);
                }
                uint end = cellStartAt(cell + 1u);
                uint64_t testsStart = PROFILE_WALK_DETAIL ? profileClock() : 0ul;
#if TRACE_RAY_ANY_HIT
                for (uint k = first; k < end && hit.kind == kKindNone; ++k) {
#else
                for (uint k = first; k < end; ++k) {
#endif
                    testPrimitive(cellPrimitiveAt(k), origin, dir, wray, hit);
                }
                if (PROFILE_WALK_DETAIL)
                    profileAdd(kPhasePrimitiveTests, testsStart);
#if TRACE_RAY_ANY_HIT
                // Any hit will do: stop at the first, or where the segment or the grid ends.
                walking = hit.kind == kKindNone && tCellExit < min(tExit, tMax);
#else
                // A grid hit is accepted only once the walk has reached the cell where it lies
                // (t <= the cell's exit), so the first accepted hit is the nearest.
                walking = hit.t > tCellExit && tCellExit < tExit;
#endif
                walking = walking &&
                          (ADAPTIVE_GRID ? stepBoxWalk(boxWalk, origin, dir) : stepWalk(walk));
            }
        }
    }
    return hit.kind != kKindNone;
}
