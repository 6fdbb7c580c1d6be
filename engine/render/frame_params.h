#pragma once
// The camera model of the scene format, reduced to the four vectors the tracer needs.
#include <cstdint>

#include "scene/scene.h"
#include "shared/gpu_types.h"

namespace prism {

// The frame's parameters for sample 0. The camera basis is computed in double (then rounded
// once) so the shader's rays match the reference's; the plane and light counts are the caller's
// to set (seedsAndLoops.zw: RayTracer::frameParams).
gpu::GpuFrameParams makeFrameParams(const Camera &camera, uint32_t width, uint32_t height,
                                    uint32_t samplesPerPixel, uint32_t maxDepth);

// Points `p` at sample `sample` of its samples per pixel: the index and the jitter's parts that
// are the same for every pixel (its stratum, the hash seeds).
void setFrameSample(gpu::GpuFrameParams &p, uint32_t sample);

} // namespace prism
