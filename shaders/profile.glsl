// In-shader phase timing for `prism-bench --profile` (docs/benchmarks.md, "Where a ray's time
// goes"). Only the build of trace.comp with PRISM_PROFILE reads clocks; in every other build the
// calls below fold away. On lavapipe the clock is os_time_get_nano (a call, ~20 ns), so each
// measured interval has the cost of one clock read taken off, calibrated at the start.
//
// All lanes of a subgroup run the same instructions, masked: a lane's clock shows the subgroup's
// time, but a lane only adds the intervals it took part in. Shadow walks and stack pushes run
// inside branches that only some lanes take, so their time is shared out to every lane of the
// bounce (subgroupMax where all its lanes are active), and shading is what remains of it. A
// phase's cost to the subgroup is then the most any lane spent there (exact when one lane took
// part in every bounce); the invocation's total less the phases is "other".

uint gClockReads = 0u;

#ifdef PRISM_PROFILE
// Also time the primitive loops inside each cell (two clock reads per cell visited).
layout(constant_id = kSpecProfileWalkDetail) const bool PROFILE_WALK_DETAIL = false;
const bool PROFILE = true;
uint64_t profileClock() {
    gClockReads += 1u;
    return clockARB();
}
#else
const bool PROFILE = false;
const bool PROFILE_WALK_DETAIL = false;
uint64_t profileClock() {
    return 0ul;
}
#endif

uint gPhaseNs[kProfileSlots];
uint64_t gClockReadNs = 0ul;
uint gBounceShadowNs = 0u; // the subgroup's shadow walks in the current bounce
uint gBouncePushNs = 0u;   // this lane's stack pushes in the current bounce

void profileStart() {
    if (PROFILE) {
        for (uint p = 0u; p < kProfileSlots; ++p)
            gPhaseNs[p] = 0u;
        uint64_t first = profileClock();
        profileClock();
        profileClock();
        gClockReadNs = (profileClock() - first) / 3ul;
        gClockReads = 0u;
    }
}

// The time since `start` (a profileClock() value) less one clock read.
uint profileElapsed(uint64_t start) {
    if (!PROFILE)
        return 0u;
    uint64_t elapsed = profileClock() - start;
    return uint(elapsed > gClockReadNs ? elapsed - gClockReadNs : 0ul);
}

void profileAdd(uint phase, uint64_t start) {
    if (PROFILE)
        gPhaseNs[phase] += profileElapsed(start);
}

// Ends a bounce's shading that began at `start`: its shadow walks and pushes, as the subgroup
// spent them, go to their phases, the rest to shading. Called where every lane of the bounce
// is active.
void profileEndShading(uint64_t start) {
    if (PROFILE) {
        uint elapsed = profileElapsed(start);
        uint shadow = subgroupMax(gBounceShadowNs);
        uint push = subgroupMax(gBouncePushNs);
        gPhaseNs[kPhaseShadowWalk] += shadow;
        gPhaseNs[kPhaseStack] += push;
        gPhaseNs[kPhaseShading] += elapsed > shadow + push ? elapsed - shadow - push : 0u;
        gBounceShadowNs = 0u;
        gBouncePushNs = 0u;
    }
}

// One atomic per subgroup and phase: the longest any lane spent in it.
void profileFlush() {
    if (PROFILE) {
        gPhaseNs[kPhaseClockReads] = gClockReads * uint(gClockReadNs);
        for (uint p = 0u; p < kProfileSlots; ++p) {
            uint ns = subgroupMax(gPhaseNs[p]);
            if (subgroupElect() && ns != 0u)
                atomicAdd(stats.phaseNs[p], uint64_t(ns));
        }
    }
}
