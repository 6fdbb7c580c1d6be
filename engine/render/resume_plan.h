#pragma once
// Resumable tracing (shaders/resume.glsl, docs/design.md): how big a tile each series of
// dispatches traces and how many walk results each of its pixels can log, so that the records
// and logs fit a fixed memory budget whatever the image size.
#include <cstdint>

namespace prism {

struct ResumePlan {
    uint32_t tileWidth = 0, tileHeight = 0; // multiples of 8 (the tracer's workgroup)
    uint32_t walkLogSize = 0;               // walk results a pixel's log holds
    uint32_t logEntryBytes = 16;            // a uvec4; two where a hit names its instance
    uint64_t recordBytes() const;           // one GpuResumeRecord per pixel of a tile
    uint64_t logBytes() const;              // walkLogSize entries per pixel
};

// The most walks one sample can make (one closest-hit walk per ray of its tree, one shadow walk
// per light per ray, one more for the AOVs), held to kMaxWalkLog; tiles as large as memoryBytes
// allows, at most the image. A hit spawns at most childRays rays: 1 for a mirror, 2 for glass
// (Fresnel reflection and refraction), 3 for glass that also reflects (its `reflect` and the
// Fresnel pair), so a tree holds at most 1 + c + ... + c^(depth-1) rays. A scene with instances
// logs 32 bytes a walk (shaders/resume.glsl).
inline constexpr uint32_t kMaxWalkLog = 256;
ResumePlan planResume(uint32_t width, uint32_t height, uint32_t maxDepth, uint32_t lights,
                      bool writeAov, uint64_t memoryBytes = uint64_t(64) << 20,
                      bool instances = false, uint32_t childRays = 3);

} // namespace prism
