// Telling whether lavapipe cut this invocation's loops short, without counting in any loop.
// lavapipe (llvmpipe's gallivm) runs 8 invocations in SIMD and gives each such group one loop
// counter of 65,535, decremented at the end of every iteration of every loop while any lane is
// active. Once it is spent, every loop the group meets exits at the end of its first iteration,
// silently: a walk stops half-way, a shadow ray sees nothing. So a loop that must run twice,
// run after all the others, ran only once exactly when the counter was spent somewhere before
// (or, harmlessly, within one iteration of it). Devices without such a limit always run it twice.
bool loopLimitReached() {
    // The trip count comes from the host (frameLoopProbe = 2) so the compiler cannot unroll
    // the loop away: an unrolled loop has no counter to read.
    uint runs = 0u;
    for (uint i = 0u; i < frameLoopProbe(frame); ++i)
        runs += 1u;
    return runs < frameLoopProbe(frame);
}
