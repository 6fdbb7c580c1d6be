// The phases of a tracer invocation that `prism-bench --profile` times with in-shader clocks
// (trace.comp compiled with PRISM_PROFILE, shaders/profile.glsl). Each is a slot of
// GpuStats::phaseNs: the nanoseconds its subgroups spent there, summed over the frame.
#ifndef PRISM_PROFILE_PHASES_H
#define PRISM_PROFILE_PHASES_H
#include "glsl_compat.h"

PRISM_NAMESPACE_BEGIN

PRISM_CONST(uint, kPhaseCamera, 0u);         // sample position and camera ray
PRISM_CONST(uint, kPhasePrimaryWalk, 1u);    // closest-hit walks of camera rays
PRISM_CONST(uint, kPhaseSecondaryWalk, 2u);  // closest-hit walks of reflected and refracted rays
PRISM_CONST(uint, kPhaseShadowWalk, 3u);     // any-hit walks of shadow rays
PRISM_CONST(uint, kPhaseShading, 4u);        // surface, material, lights, new rays (no walks)
PRISM_CONST(uint, kPhasePrimitiveTests, 5u); // inside the walks: the primitive loops (detail only)
PRISM_CONST(uint, kPhaseTotal, 6u);          // the whole invocation
PRISM_CONST(uint, kPhaseStack, 7u);          // the ray stack: pops, and pushes during shading
PRISM_CONST(uint, kPhaseOutput, 8u);         // loop-limit probe, image and counter writes
PRISM_CONST(uint, kPhaseClockReads, 9u);     // the profile's own clock reads, estimated
PRISM_CONST(uint, kProfileSlots, 10u);

PRISM_NAMESPACE_END

#endif
