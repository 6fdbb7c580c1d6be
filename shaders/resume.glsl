// Resumable tracing (docs/design.md, "Resumable tracing"). lavapipe runs at most 65,535 loop
// iterations per subgroup and dispatch (loop_limit.glsl); a sample that needs more, such as
// 40,000 spheres without a grid, is traced over several dispatches. Each lane charges its loop
// iterations to a budget; a walk that would overrun it stops between two primitive tests and the
// pixel's record keeps where (the walker's state in its cell, the tests done there, the best
// hit so far). The next dispatch replays the sample from the start: the walks that finished
// before return their logged results at the cost of one read, the interrupted walk picks up
// where it stopped, so every dispatch makes progress, and the sample's final replay shades it
// exactly as one uninterrupted invocation would. With RESUMABLE off all of this folds away.

// Loop iterations a lane may charge per dispatch (kResumeLaneBudget: why it is safe).
layout(constant_id = kSpecResumeLaneBudget) const uint LANE_BUDGET = kResumeLaneBudget;

uint gBudgetUsed = 0u;
bool gOutOfBudget = false; // this lane stopped a walk; the rest of the sample is skipped
bool gLogFull = false;     // the sample needs more walks than the log holds
uint gWalkCount = 0u;      // walks begun in this sample, replayed ones included
uint gRecord = 0u;         // this pixel's record (and log) in the tile
GpuResumeRecord gResume;   // the record as this dispatch found it

void chargeBudget(uint iterations) {
    if (RESUMABLE)
        gBudgetUsed += iterations;
}

uint budgetLeft() {
    return gBudgetUsed < LANE_BUDGET ? LANE_BUDGET - gBudgetUsed : 0u;
}

// An instance's walk is not interrupted: the walk stops before one unless this much budget is
// left (a prototype's regular grid costs a few hundred iterations a walk; one that costs more
// overruns the budget, and a cut that follows is refused by name). A quarter of a small test
// budget, so that a resumed walk still gets past its first instance.
const uint kInstanceWalkReserve = LANE_BUDGET / 4u < 1024u ? LANE_BUDGET / 4u : 1024u;

// Log entries: x t, y kind << 29 | index (kind 7: none; the host keeps indices below 2^29), zw
// barycentrics; in a scene with instances a second uvec4 whose x is the hit's instance.
const uint kLogEntryWords = HAS_INSTANCES ? 2u : 1u;

uvec4 packHit(Hit hit) {
    uint kind = hit.kind == kKindNone ? 7u : hit.kind;
    return uvec4(floatBitsToUint(hit.t), (kind << 29u) | hit.index, floatBitsToUint(hit.b12));
}

Hit unpackHit(uvec4 packed, uint instance) {
    Hit hit;
    hit.t = uintBitsToFloat(packed.x);
    hit.kind = packed.y >> 29u == 7u ? kKindNone : packed.y >> 29u;
    hit.index = packed.y & 0x1FFFFFFFu;
    hit.b12 = uintBitsToFloat(packed.zw);
    hit.instance = instance;
    return hit;
}

uint walkLogEntry(uint walk) {
    return (gRecord * frameWalkLogSize(frame) + walk) * kLogEntryWords;
}

Hit loggedHit(uint walk) {
    uint entry = walkLogEntry(walk);
    return unpackHit(walkLog[entry], HAS_INSTANCES ? walkLog[entry + 1u].x : kNoInstance);
}

void logWalk(uint walk, Hit hit) {
    if (walk < frameWalkLogSize(frame)) {
        walkLog[walkLogEntry(walk)] = packHit(hit);
        if (HAS_INSTANCES)
            walkLog[walkLogEntry(walk) + 1u] = uvec4(hit.instance, 0u, 0u, 0u);
    } else {
        gLogFull = true;
    }
}

// Where a walk resumes: the walker's state on entering the cell it was in (the regular grid's
// cell and tNext, the adaptive grid's voxel and t), and the tests it had done there. A walk
// that runs out of budget sets `interrupted` and leaves its own state here.
struct WalkResume {
    bool resuming;
    ivec3 cell;
    vec3 t;
    uint skipTests;
    bool interrupted;
};

GpuResumeRecord gInterrupted; // what this dispatch leaves for the next, once gOutOfBudget

void interruptSample(uint walk, WalkResume resume, Hit best) {
    gOutOfBudget = true;
    gInterrupted.progress = uvec4(walk, 0u, resume.skipTests, 1u);
    gInterrupted.bestHit = packHit(best);
    gInterrupted.walker = uvec4(resume.cell, best.instance);
    gInterrupted.walkerT = uvec4(floatBitsToUint(resume.t), 0u);
}
