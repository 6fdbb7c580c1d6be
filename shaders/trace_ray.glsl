// The grid walk, written once and compiled twice by traverse.glsl: as TRACE_RAY_NAME with
// TRACE_RAY_ANY_HIT 0 (closest hit) and 1 (any hit, for shadow rays). The mode is a preprocessor
// switch rather than a bool parameter so that each mode compiles to exactly the loop it had as
// a walker of its own; the parameter, constant at every call, measured 3% slower on lavapipe.
// Hits count on the open segment 0 < t < tMax.
//
// TRACE_WALK_NAME is the walk itself; `hit` comes in as the best hit so far (t = tMax when there
// is none). The grid's walk starts at gridFrom along the ray: nothing in the grid lies nearer
// (a camera ray's tile start, render/traced_tiles.h; 0 for every other ray). In resumable
// tracing (resume.glsl) it skips the tests of the cells `resume` says an earlier dispatch did,
// and stops, setting resume.interrupted, where the lane's budget runs out.
bool TRACE_WALK_NAME(vec3 origin, vec3 dir, float gridFrom, inout Hit hit,
                     inout WalkResume resume) {
    if (HAS_PLANES) {
        chargeBudget(framePlaneCount(frame));
        for (uint i = 0u; i < framePlaneCount(frame); ++i) {
            float t;
            if (intersectPlane(origin, dir, planeEquation(i), hit.t, t)) {
                recordHit(hit, t, kKindPlane, i);
#if TRACE_RAY_ANY_HIT
                return true;
#endif
            }
        }
    }
#ifndef PRISM_PLANES_ONLY // (its module has no grid: trace_bindings.glsl)
    if (HAS_SPHERES || HAS_TRIANGLES || HAS_INSTANCES) {
        vec3 invDir = 1.0 / dir;
        float tEnter, tExit;
        bool crosses = clipToGrid(origin, invDir, tEnter, tExit);
        tEnter = max(tEnter, gridFrom);
        if (crosses && tEnter <= tExit && tEnter < hit.t) {
            WatertightRay wray = makeWatertightRay(dir);
            // A regular grid is walked with 3D-DDA, an adaptive one from cell box to cell box.
            GridWalk walk;
            BoxWalk boxWalk;
            if (ADAPTIVE_GRID)
                boxWalk = startBoxWalk(origin, dir, tEnter);
            else
                walk = startWalk(origin, dir, invDir, tEnter);
            if (RESUMABLE && resume.resuming) { // where an earlier dispatch stopped
                if (ADAPTIVE_GRID) {
                    boxWalk.voxel = resume.cell;
                    boxWalk.t = resume.t.x;
                } else {
                    walk.cell = resume.cell;
                    walk.tNext = resume.t;
                }
            }
            bool walking = true;
            // Where the ray enters the current cell (instances walk only that part of it). A
            // resumed regular-grid walk does not know it: from the grid's entry is safe.
            float tCellEnter = tEnter;
            bool progressed = !(RESUMABLE && resume.resuming); // a test since resuming
            while (walking) {
                uint cell, first, end;
                float tCellExit;
                ivec3 entryVoxel = boxWalk.voxel; // the adaptive walker before entering the cell
                float entryT = boxWalk.t;
                if (ADAPTIVE_GRID) {
                    tCellEnter = entryT;
                    cell = enterBoxCell(boxWalk, origin, dir, invDir);
                    first = boxWalk.firstPrimitive;
                    end = boxWalk.endPrimitive;
                    tCellExit = boxWalk.t;
                } else {
                    tCellExit = min(min(walk.tNext.x, walk.tNext.y), walk.tNext.z);
                    cell = cellIndex(walk.cell);
                    first = cellStartAt(cell);
                    end = cellStartAt(cell + 1u);
                }
                uint cellFirst = first;
                if (RESUMABLE) {
                    first = min(first + resume.skipTests, end); // tested in an earlier dispatch
                    resume.skipTests = 0u;
                    // The cell's pass, the primitive loop's extra pass, and the voxel-map
                    // descent: at most one level per bit of voxels.w, plus its extra pass.
                    chargeBudget(ADAPTIVE_GRID ? 4u + uint(header.voxels.w) : 4u);
                    // A test costs one: the cell's share of the budget is known now. (An
                    // instance's costs its walk: the loop below charges as it goes.)
                    uint left = budgetLeft();
                    if (!HAS_INSTANCES && end - first > left) {
                        end = first + left;
                        resume.interrupted = true;
                        resume.cell = ADAPTIVE_GRID ? entryVoxel : walk.cell;
                        resume.t = ADAPTIVE_GRID ? vec3(entryT, 0.0, 0.0) : walk.tNext;
                        resume.skipTests = end - cellFirst;
                    }
                    if (!HAS_INSTANCES)
                        chargeBudget(end - first);
                }
                uint64_t testsStart = PROFILE_WALK_DETAIL ? profileClock() : 0ul;
#if TRACE_RAY_ANY_HIT
                for (uint k = first; k < end && hit.kind == kKindNone; ++k) {
#else
                for (uint k = first; k < end; ++k) {
#endif
                    if (CELL_TRIANGLES) { // no id: the entry is the triangle
                        testCellTriangle(ADAPTIVE_GRID ? cellRecordTriangleRow(cell, k) : 3u * k,
                                         origin, dir, wray, hit);
                        continue;
                    }
                    if (CELL_SPHERES) { // no id: the entry is the sphere
                        testCellSphere(k, origin, dir, hit);
                        continue;
                    }
                    // Not enough left for this test (an instance's walk needs the reserve):
                    // go on from here next time. A resumed walk always makes its first test,
                    // so that a replay that spent most of the budget cannot stall the sample.
                    uint id = cellPrimitiveAt(k);
                    bool instanceNext = HAS_INSTANCES && id >= header.idEnd[kKindTriangle];
                    if (RESUMABLE && HAS_INSTANCES && progressed &&
                        budgetLeft() < (instanceNext ? kInstanceWalkReserve : 4u)) {
                        resume.interrupted = true;
                        resume.cell = ADAPTIVE_GRID ? entryVoxel : walk.cell;
                        resume.t = ADAPTIVE_GRID ? vec3(entryT, 0.0, 0.0) : walk.tNext;
                        resume.skipTests = k - cellFirst;
                        break;
                    }
                    // The test, and the extra passes of an instance walk's two loops, which
                    // the subgroup runs for every test where some lane tests an instance or
                    // none does (masked; its lanes charge their own walks' passes).
                    if (RESUMABLE && HAS_INSTANCES)
                        chargeBudget(4u);
                    progressed = true;
                    testPrimitive(id, origin, dir, wray, TRACE_RAY_ANY_HIT != 0, tCellEnter,
                                  tCellExit, hit);
                }
                if (PROFILE_WALK_DETAIL)
                    profileAdd(kPhasePrimitiveTests, testsStart);
                if (RESUMABLE && resume.interrupted)
                    break;
#if TRACE_RAY_ANY_HIT
                // Any hit will do: stop at the first, or where the segment or the grid ends.
                walking = hit.kind == kKindNone && tCellExit < min(tExit, hit.t); // hit.t: tMax
#else
                // A grid hit is accepted only once the walk has reached the cell where it lies
                // (t <= the cell's exit), so the first accepted hit is the nearest.
                walking = hit.t > tCellExit && tCellExit < tExit;
#endif
                walking = walking &&
                          (ADAPTIVE_GRID ? stepBoxWalk(boxWalk, origin, dir) : stepWalk(walk));
                tCellEnter = tCellExit;
            }
        }
    }
#endif
    return hit.kind != kKindNone;
}

// The walk as the tracer calls it. In resumable tracing a walk an earlier dispatch finished
// returns its logged result; once this dispatch has interrupted a walk, later walks of the
// sample return nothing (the sample is replayed next time, and nothing of it is kept now).
bool TRACE_RAY_NAME(vec3 origin, vec3 dir, float gridFrom, float tMax, out Hit hit) {
    hit.t = tMax;
    hit.kind = kKindNone;
    hit.index = 0u;
    hit.b12 = vec2(0.0);
    hit.instance = kNoInstance;
    WalkResume resume = WalkResume(false, ivec3(0), vec3(0.0), 0u, false);
    uint walk = 0u;
    if (RESUMABLE) {
        walk = gWalkCount++;
        if (walk < gResume.progress.x) {
            hit = loggedHit(walk);
            return hit.kind != kKindNone;
        }
        if (gOutOfBudget || gLogFull)
            return false;
        chargeBudget(8u); // the walk's loops' extra passes
        if (walk == gResume.progress.x && gResume.progress.w != 0u) {
            resume.resuming = true;
            resume.cell = ivec3(gResume.walker.xyz);
            resume.t = uintBitsToFloat(gResume.walkerT.xyz);
            resume.skipTests = gResume.progress.z;
            Hit best = unpackHit(gResume.bestHit, gResume.walker.w);
            if (best.kind != kKindNone)
                hit = best;
        }
    }
    TRACE_WALK_NAME(origin, dir, gridFrom, hit, resume);
    // A hit's entry becomes its sphere once the walk is done (an interrupted walk keeps the
    // entry: it goes on from there). Shadow rays need no index.
    if (TRACE_RAY_ANY_HIT == 0 && !(RESUMABLE && resume.interrupted))
        resolveCellHit(hit);
    if (RESUMABLE) {
        if (resume.interrupted)
            interruptSample(walk, resume, hit);
        else
            logWalk(walk, hit);
    }
    return hit.kind != kKindNone;
}
