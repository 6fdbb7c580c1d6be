#version 460
// Prism's tracer: one invocation per pixel, one sample per dispatch. Whitted ray tracing
// (Blinn-Phong + shadows + reflection + refraction) without recursion: the ray tree is walked
// with an explicit stack. Same semantics as the CPU reference (engine/reference).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#ifdef PRISM_PROFILE
#extension GL_ARB_shader_clock : require // profile.glsl
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#include "shared/gpu_types.h"
#include "shared/trace_interface.h"
#include "shared/sampling.h"
#include "trace_bindings.glsl"
#include "loop_limit.glsl"
#include "profile.glsl"
#include "intersect.glsl"
#include "traverse.glsl"
#include "surface.glsl"
#include "surface_maps.glsl"

uint gShadowRays = 0u;
uint gSecondaryRays = 0u;

// Spec camera model: perspective rays leave the eye; parallel rays leave the image plane.
void cameraRay(vec2 pixelPosition, out vec3 origin, out vec3 dir) {
    vec2 uv = pixelPosition / vec2(frame.image.xy);
    float x = 2.0 * uv.x - 1.0, y = 1.0 - 2.0 * uv.y;
    if (isParallelCamera(frame)) {
        origin = frame.eye.xyz + x * frame.du.xyz + y * frame.dv.xyz;
        dir = frame.forward.xyz;
    } else {
        origin = frame.eye.xyz;
        dir = normalize(frame.forward.xyz + x * frame.du.xyz + y * frame.dv.xyz);
    }
}

vec2 samplePosition(uvec2 pixel, uint pixelIndex) {
    if (frameSamplesPerPixel(frame) == 1u)
        return vec2(pixel) + 0.5;
    // The stratum and the hash seeds come with the frame (the same for every pixel).
    vec2 jitter = vec2(bitsTo01(pcgHash(pixelIndex ^ frame.seedsAndLoops.x)),
                       bitsTo01(pcgHash(pixelIndex ^ frame.seedsAndLoops.y)));
    return vec2(pixel) + (frame.strata.xy + jitter) / frame.strata.zw;
}

// Ambient + Blinn-Phong from every light whose shadow ray is clear. The normals face the
// viewer: the geometric one, the unmapped shading one (`smoothN`) and `n`, which shades (bent
// by normal and bump maps where the material has them).
vec3 directLight(Surface s, vec3 facingGeometric, vec3 smoothN, vec3 n, vec3 view, vec3 color,
                 GpuMaterial m, uint pixelIndex, uint sampleIndex, uint depth) {
    vec3 result = materialAmbient(m) * color * header.ambient.rgb;
    uint lights = frameLightCount(frame);
    for (uint l = 0u; l < lights; ++l) {
        // resume.glsl: the light's loop pass, and the strata loops of an area light's sample
        // (sampling.h: from sqrt's estimate, each runs at most twice, three times a sample)
        chargeBudget(HAS_AREA_LIGHTS ? 32u : 8u);
        uint shadowWalkNs = 0u;
        GpuLight light = lightAt(l);
        vec3 toLight = normalize(lightPosition(light) - s.position);
        float nDotL = dot(n, toLight);
        if (nDotL > 0.0) {
            bool visible = true;
            if (HAS_SHADOWS) {
                vec3 target = lightPosition(light);
                if (HAS_AREA_LIGHTS && lightRadius(light) > 0.0) {
                    uint dim = PRISM_DIM_LIGHT_BASE + 2u * ((depth - 1u) * lights + l);
                    vec2 u = stratifiedPair(pixelIndex, sampleIndex, frameSamplesPerPixel(frame),
                                            dim);
                    float z = 1.0 - 2.0 * u.x;
                    float rxy = sqrt(max(0.0, 1.0 - z * z));
                    float phi = 2.0 * kPi * u.y;
                    target += lightRadius(light) * vec3(rxy * cos(phi), rxy * sin(phi), z);
                }
                // A target below the surface's own horizon (an area-light sample) is shadowed
                // by the surface itself. With vertex normals the surface is the smooth one they
                // describe: its point and normal (no stair-step terminator on coarse meshes).
                // A mapped normal's horizon is not the surface's: a light behind the surface
                // stays dark however the map leans (no leaks).
                vec3 from = s.shadowPosition;
                vec3 horizon = s.smoothed ? smoothN : facingGeometric;
                visible = dot(target - from, horizon) > 0.0;
                if (visible) {
                    vec3 origin = offsetOrigin(from, s.offsetFloor, horizon, target - from);
                    vec3 toTarget = target - origin;
                    float distance = length(toTarget);
                    gShadowRays += 1u;
                    uint64_t walkStart = profileClock();
                    visible = !traceOccluded(origin, toTarget / distance, distance);
                    shadowWalkNs = profileElapsed(walkStart);
                }
            }
            if (visible) {
                vec3 halfway = normalize(toLight + view);
                // pow(0, 0) is undefined in GLSL; shininess 0 means a constant 1, as in C++.
                float shininess = materialShininess(m);
                float specular = shininess > 0.0 ? pow(max(0.0, dot(n, halfway)), shininess) : 1.0;
                result += lightColor(light) *
                          (materialDiffuse(m) * color * nDotL + materialSpecular(m) * specular);
            }
        }
        if (PROFILE) // every lane shading this bounce is active here
            gBounceShadowNs += subgroupMax(shadowWalkNs);
    }
    return result;
}

struct PendingRay {
    vec3 origin;
    vec3 dir;
    vec3 weight;
    uint depth;
};

PendingRay gStack[STACK_SIZE];
uint gStackSize = 0u;

void pushRay(vec3 origin, vec3 dir, vec3 weight, uint depth) {
    uint64_t start = profileClock();
    if (gStackSize < STACK_SIZE) // sized 2 * maxDepth - 1: never full, but never overrun
        gStack[gStackSize++] = PendingRay(origin, dir, weight, depth);
    if (PROFILE)
        gBouncePushNs += profileElapsed(start);
}

// The camera ray's grid walk starts at cameraFrom (its tile's start distance).
vec3 traceSample(vec3 origin, vec3 dir, float cameraFrom, uint pixelIndex, uint sampleIndex) {
    uint maxDepth = frameMaxDepth(frame);
    vec3 radiance = vec3(0.0);
    pushRay(origin, dir, vec3(1.0), 1u);
    while (gStackSize > 0u) {
        chargeBudget(8u); // resume.glsl
        uint64_t popStart = profileClock();
        PendingRay ray = gStack[--gStackSize];
        profileAdd(kPhaseStack, popStart);
        if (ray.depth > 1u)
            gSecondaryRays += 1u;
        Hit hit;
        uint64_t walkStart = profileClock();
        bool hitSomething =
            traceClosest(ray.origin, ray.dir, ray.depth == 1u ? cameraFrom : 0.0, kInfinity, hit);
        profileAdd(ray.depth > 1u ? kPhaseSecondaryWalk : kPhasePrimaryWalk, walkStart);
        uint64_t shadingStart = profileClock();
        if (!hitSomething) {
            radiance += ray.weight * missColor(ray.dir);
        } else {
            Surface s = surfaceAt(ray.origin, ray.dir, hit);
            GpuMaterial m = materialAt(s.material);
            vec3 view = -ray.dir;
            vec3 ng = dot(s.geometricNormal, view) < 0.0 ? -s.geometricNormal : s.geometricNormal;
            // The side is decided by the unmapped shading normal, so a map never flips it; the
            // map bends the normal of the side it was made for (seen from behind, a bump is a
            // dent), then it is turned with the rest.
            bool back = dot(s.shadingNormal, view) < 0.0;
            vec3 smoothN = back ? -s.shadingNormal : s.shadingNormal;
            vec3 n = smoothN;
            if (HAS_SURFACE_MAPS) {
                vec3 mapped = mappedNormal(s, m);
                n = back ? -mapped : mapped;
            }
            vec3 color = materialColor(m);
            if (HAS_TEXTURES && materialHasTexture(m))
                color *= textureColor(materialTexture(m), s.uv);
            radiance += ray.weight * directLight(s, ng, smoothN, n, view, color, m, pixelIndex,
                                                 sampleIndex, ray.depth);
            if (ray.depth < maxDepth) {
                vec3 reflected = reflect(ray.dir, n);
                if (HAS_REFLECTION && materialReflect(m) > 0.0)
                    pushRay(offsetOrigin(s.position, s.offsetFloor, ng, reflected), reflected,
                            ray.weight * materialReflect(m), ray.depth + 1u);
                if (HAS_TRANSMISSION && materialTransmit(m) > 0.0) {
                    float ior = materialIor(m);
                    bool entering = dot(ray.dir, s.geometricNormal) < 0.0;
                    float eta = entering ? 1.0 / ior : ior;
                    float cosI = -dot(ray.dir, n);
                    float k = 1.0 - eta * eta * (1.0 - cosI * cosI);
                    vec3 weight = ray.weight * materialTransmit(m);
                    if (k < 0.0) { // total internal reflection
                        pushRay(offsetOrigin(s.position, s.offsetFloor, ng, reflected), reflected, weight,
                                ray.depth + 1u);
                    } else {
                        float f0 = (ior - 1.0) / (ior + 1.0);
                        f0 *= f0;
                        float x = max(0.0, 1.0 - cosI);
                        float fresnel = f0 + (1.0 - f0) * (x * x) * (x * x) * x; // Schlick
                        vec3 refracted = normalize(eta * ray.dir + (eta * cosI - sqrt(k)) * n);
                        pushRay(offsetOrigin(s.position, s.offsetFloor, ng, reflected), reflected,
                                weight * fresnel, ray.depth + 1u);
                        pushRay(offsetOrigin(s.position, s.offsetFloor, ng, refracted), refracted,
                                weight * (1.0 - fresnel), ray.depth + 1u);
                    }
                }
            }
        }
        profileEndShading(shadingStart);
    }
    return radiance;
}

void addResumeCounts(bool unfinished, bool stuck) {
    uvec2 total = subgroupAdd(uvec2(unfinished ? 1u : 0u, stuck ? 1u : 0u));
    if (subgroupElect()) {
        if (total.x != 0u) atomicAdd(stats.unfinishedPixels, uint64_t(total.x));
        if (total.y != 0u) atomicAdd(stats.stuckPixels, uint64_t(total.y));
    }
}

// Each lane adds its own non-zero counts to its workgroup's slot (GpuStats::rayCounts).
void addCounts(uint primary, uint shadow, uint secondary, uint loopCut) {
    // Rows of workgroups offset by 7 slots: resumable tracing's 2D dispatch gives each of
    // lavapipe's threads its own rows, which would otherwise meet on the same slots.
    uint slot = (gl_WorkGroupID.x + 7u * gl_WorkGroupID.y) % kRayCountSlots;
    if (primary != 0u) atomicAdd(stats.rayCounts[slot].primary, uint64_t(primary));
    if (shadow != 0u) atomicAdd(stats.rayCounts[slot].shadow, uint64_t(shadow));
    if (secondary != 0u) atomicAdd(stats.rayCounts[slot].secondary, uint64_t(secondary));
    if (loopCut != 0u) atomicAdd(stats.rayCounts[slot].loopCut, uint64_t(loopCut));
}

// The camera rays of a tile (of the frame's tile list) that lie inside the image: one lane
// adds them all, as they are known from the tile's place (every such pixel traces its ray).
uint tileCameraRays(uvec2 tileOrigin) {
    if (gl_LocalInvocationIndex != 0u)
        return 0u;
    uvec2 inside = min(gl_WorkGroupSize.xy, frame.image.xy - tileOrigin);
    return inside.x * inside.y;
}

void main() {
    // The pixel: resumable tracing dispatches a rectangle of tiles from the frame's tile origin;
    // otherwise each workgroup takes one entry of the frame's tile list (render/traced_tiles.h).
    uvec2 pixel;
    uint cameraRays = 0u;   // this lane's share of the workgroup's camera rays, to count
    float cameraFrom = 0.0; // where camera rays' grid walks start
    if (RESUMABLE) {
        pixel = uvec2(frameTileOriginX(frame), frameTileOriginY(frame)) + gl_GlobalInvocationID.xy;
    } else {
        uint entry = frameTileListStart(frame) + gl_WorkGroupID.y * gl_NumWorkGroups.x +
                     gl_WorkGroupID.x;
        if (entry >= frameTileListEnd(frame))
            return; // the last row of workgroups runs past the range: the whole group leaves
        uvec2 tile = tileListEntry(entry);
        // lavapipe runs each 8 consecutive invocations as one SIMD group: each gets a 4x2
        // block of the tile rather than a row of 8, so its rays stay closer together and share
        // more cells (docs/benchmarks.md, "4x2 blocks"). A 32-wide warp covers the same 8x4 half
        // of the tile either way.
        uint i = gl_LocalInvocationIndex, group = i >> 3u, lane = i & 7u;
        pixel = tileListOrigin(tile) +
                uvec2((group & 1u) * 4u + (lane & 3u), (group >> 1u) * 2u + (lane >> 2u));
        cameraFrom = tileListStart(tile);
        cameraRays = tileCameraRays(tileListOrigin(tile));
    }
    profileStart();
    uint64_t invocationStart = profileClock();
    bool inside = all(lessThan(pixel, frame.image.xy));
    if (RESUMABLE) { // resume.glsl: a finished pixel waits for its tile's last dispatch
        gRecord = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * 8u) + gl_GlobalInvocationID.x;
        gResume = resumeRecords[gRecord];
        inside = inside && gResume.progress.y == 0u;
        chargeBudget(32u); // the strata loops of the sample's position (sampling.h)
    }
    // Every sample number of this pixel is drawn for this key (the index under seed 0).
    uint pixelIndex = samplingKey(pixel.y * frame.image.x + pixel.x, frameSeed(frame));
    uint sampleIndex = frameSampleIndex(frame);
    vec3 radiance = vec3(0.0);
    vec4 aov = vec4(0.0, 0.0, 0.0, kInfinity);
    if (inside) {
        vec3 origin, dir;
        uint64_t cameraStart = profileClock();
        cameraRay(samplePosition(pixel, pixelIndex), origin, dir);
        profileAdd(kPhaseCamera, cameraStart);
#ifdef PRISM_BACKGROUND_ONLY
        // Tiles whose camera rays provably miss everything (render/traced_tiles.h): no walk,
        // no shading, so glslang leaves them out and lavapipe creates this variant in
        // milliseconds. The AOVs keep their miss values.
        radiance = missColor(dir);
#else
        radiance = traceSample(origin, dir, cameraFrom, pixelIndex, sampleIndex);
        if (WRITE_AOV && sampleIndex == 0u) {
            cameraRay(vec2(pixel) + 0.5, origin, dir);
            Hit hit;
            if (traceClosest(origin, dir, cameraFrom, kInfinity, hit)) {
                vec3 ng = surfaceAt(origin, dir, hit).geometricNormal;
                aov = vec4(dot(ng, dir) > 0.0 ? -ng : ng, hit.t);
            }
        }
#endif
    }
    uint64_t outputStart = profileClock();
    // Last, after every other loop of the invocation (loop_limit.glsl).
    bool cut = loopLimitReached();
    // Resumable: a sample stopped by its budget (or, never expected, by lavapipe's limit) keeps
    // nothing of this dispatch but where it got to; a finished one is written and marked done.
    bool unfinished = RESUMABLE && inside && (cut || gOutOfBudget || gLogFull);
    bool stuck = false;
    if (unfinished) {
        // Never expected: a cut despite the budget, a full log, or no step forward.
        stuck = cut || gLogFull ||
                (gOutOfBudget && gInterrupted.progress == gResume.progress &&
                 gInterrupted.walker == gResume.walker && gInterrupted.walkerT == gResume.walkerT);
        if (!stuck)
            resumeRecords[gRecord] = gInterrupted;
        inside = false;
        gShadowRays = 0u;
        gSecondaryRays = 0u;
    } else if (RESUMABLE && inside) {
        resumeRecords[gRecord].progress.y = 1u;
    }
    if (RESUMABLE)
        addResumeCounts(unfinished && !stuck, stuck);
    if (inside) {
        if (cut)
            radiance = vec3(1.0, 0.0, 1.0); // magenta: the host refuses to save such an image
        ivec2 stored = ivec2(pixel - frameStoreOrigin(frame));
        vec4 sum = sampleIndex == 0u ? vec4(0.0) : imageLoad(accumImage, stored);
        imageStore(accumImage, stored, sum + vec4(radiance, 1.0));
        if (WRITE_AOV && sampleIndex == 0u)
            imageStore(aovImage, stored, aov);
    }
    // Resumable: a pixel's camera ray counts once, when its sample is finished.
    if (RESUMABLE)
        cameraRays = inside ? 1u : 0u;
    addCounts(cameraRays, gShadowRays, gSecondaryRays, (inside && cut) ? 1u : 0u);
    profileAdd(kPhaseOutput, outputStart);
    profileAdd(kPhaseTotal, invocationStart);
    profileFlush();
}
