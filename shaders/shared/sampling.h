// Deterministic sample numbers shared by the GLSL tracer and the C++ reference, so both trace
// exactly the same anti-aliasing offsets and area-light points and their images can be
// compared pixel for pixel. Pure 32-bit integer maths: bit-identical on CPU and GPU.
#ifndef PRISM_SAMPLING_H
#define PRISM_SAMPLING_H
#include "glsl_compat.h"

PRISM_NAMESPACE_BEGIN

// PCG-RXS-M-XS hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering").
PRISM_INLINE uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Sample dimensions: 0 and 1 jitter the pixel; area-light points use
// kDimLightBase + 2 * (depth0 * lightCount + light) and the next one (depth0 = ray depth - 1).
#define PRISM_DIM_PIXEL_X 0u
#define PRISM_DIM_PIXEL_Y 1u
#define PRISM_DIM_LIGHT_BASE 2u

// The number a pixel's samples are drawn for: its index (y * width + x, in the whole image, so
// that a region or tile draws what the whole image would), or under a sampling seed other than
// 0 (prism-render --seed, the Python module's seed=) a hash of index and seed, a permutation of
// the pixels for each seed. Seed 0 is the index itself: images made before seeds existed are
// unchanged.
PRISM_INLINE uint samplingKey(uint pixelIndex, uint seed) {
    return seed == 0u ? pixelIndex : pcgHash(pixelIndex ^ pcgHash(seed ^ 0x5EED5EEDu));
}

// A uniform number in [0, 1) for (pixel, sample, dimension); 24 bits, exact in float. The seed
// is the part that does not depend on the pixel: the host computes it once per dispatch for the
// pixel jitter (GpuFrameParams::seedsAndLoops).
PRISM_INLINE uint sampleSeed(uint sampleIndex, uint dimension) {
    return pcgHash(sampleIndex ^ pcgHash(dimension));
}
PRISM_INLINE uint sampleBits(uint pixelIndex, uint sampleIndex, uint dimension) {
    return pcgHash(pixelIndex ^ sampleSeed(sampleIndex, dimension));
}
PRISM_INLINE float bitsTo01(uint bits) {
    return float(bits >> 8u) * (1.0f / 16777216.0f);
}
PRISM_INLINE float sample01(uint pixelIndex, uint sampleIndex, uint dimension) {
    return bitsTo01(sampleBits(pixelIndex, sampleIndex, dimension));
}

// Strata for N samples per pixel: columns = floor(sqrt(N)), rows = ceil(N / columns).
PRISM_INLINE uint strataColumns(uint samplesPerPixel) {
    uint c = uint(sqrt(float(samplesPerPixel)));
    while ((c + 1u) * (c + 1u) <= samplesPerPixel)
        c += 1u; // guard against sqrt rounding
    while (c * c > samplesPerPixel)
        c -= 1u;
    return c < 1u ? 1u : c;
}
PRISM_INLINE uint strataRows(uint samplesPerPixel) {
    uint c = strataColumns(samplesPerPixel);
    return (samplesPerPixel + c - 1u) / c;
}

// Two uniform numbers for an area-light point, stratified across the pixel's samples: sample
// `sampleIndex` of `samplesPerPixel` lands in its own stratum of the unit square (a grid where
// the count is a square-ish product, else strips), so soft shadows converge much faster than
// with independent points. A per-pixel, per-dimension rotation of the stratum index keeps the
// light strata uncorrelated with the pixel-jitter strata.
PRISM_INLINE vec2 stratifiedPair(uint pixelIndex, uint sampleIndex, uint samplesPerPixel,
                                 uint dimension) {
    uint columns = strataColumns(samplesPerPixel), rows = strataRows(samplesPerPixel);
    if (columns * rows != samplesPerPixel) {
        columns = 1u;
        rows = samplesPerPixel;
    }
    uint k = (sampleIndex + sampleBits(pixelIndex, 0xA511E9B3u, dimension)) % samplesPerPixel;
    float jx = sample01(pixelIndex, sampleIndex, dimension);
    float jy = sample01(pixelIndex, sampleIndex, dimension + 1u);
    return vec2((float(k % columns) + jx) / float(columns),
                (float(k / columns) + jy) / float(rows));
}

PRISM_NAMESPACE_END
#endif
