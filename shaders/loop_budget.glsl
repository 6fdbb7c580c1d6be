// Counting loop iterations the way lavapipe does, so no pixel is ever silently cut short.
// lavapipe runs 8 invocations in SIMD and keeps ONE counter per SIMD group, decremented at every
// back-edge of every loop while any lane is active. A lane's own count can therefore be lower
// than the group's; taking the subgroup maximum at the end of each iteration of a loop that
// contains loops, and after each such loop, keeps every active lane's count >= the group's.
uint gLoopIterations = 0u;
bool gOverBudget = false;

// Call at the top of every loop iteration; false means "stop: the budget is spent".
bool loopTick() {
    if (LOOP_BUDGET == 0u)
        return true;
    gLoopIterations += 1u;
    if (gLoopIterations >= LOOP_BUDGET)
        gOverBudget = true;
    return !gOverBudget;
}

// Call where lanes reconverge after loops (see above).
void loopSync() {
    if (LOOP_BUDGET == 0u)
        return;
    gLoopIterations = subgroupMax(gLoopIterations);
    gOverBudget = subgroupAny(gOverBudget);
}
