#pragma once
// Which tracer features a scene needs, and the options a caller may override; each feature
// becomes a specialization constant (shaders/shared/trace_interface.h) so a scene pays only for
// what it uses (no refraction code when nothing transmits, ...).
#include <cstdint>
#include <vector>

#include "accel/grid.h"
#include "render/image_region.h"
#include "render/traced_tiles.h"
#include "scene/scene.h"
#include "vk/descriptor_set.h"

namespace prism {

struct TracerOptions {
    uint32_t maxDepth = 5;
    // The pixels to trace (render/image_region.h); empty: the whole image. The accumulation
    // and AOV images hold only the 8x8 tiles round them.
    PixelRect region;
    bool writeAov = false;
    bool shadows = true;
    bool reflection = true;   // false: off even where materials reflect (feature-cost study)
    bool transmission = true; // likewise for refraction
    // Read grid cells, spheres and triangles through uniform texel buffers rather than storage
    // buffers: 10-18% faster on lavapipe (measured in docs/benchmarks.md).
    bool texelBuffers = true;
    // Largest storage buffer to use, in bytes; 0: the device's maxStorageBufferRange. Tests
    // lower it to check that an oversized array is refused, or read through its texel view.
    uint64_t storageBufferLimit = 0;
    // prism-bench --profile: 0 the ordinary tracer; 1 the tracer with in-shader clocks per
    // phase (shaders/profile.glsl; needs a context with shaderClock); 2 also around the
    // primitive loops inside the walks.
    uint32_t profile = 0;
    // Resumable tracing (shaders/resume.glsl) from the first frame rather than only after a
    // frame overran lavapipe's loop limit; with a lane budget (loop iterations per dispatch,
    // 0: the shader's default) and a memory budget for its records and logs. Tests use small
    // budgets to interrupt ordinary scenes everywhere.
    bool resumable = false;
    uint32_t resumeLaneBudget = 0;
    uint64_t resumeMemoryBytes = uint64_t(64) << 20;
    // For the studies only (prism-bench variants, docs/studies): the original's fixed offset of
    // secondary-ray origins along the normal, in scene units (0: Prism's relative offset), and
    // the common Moller-Trumbore triangle test instead of the watertight one.
    float fixedRayOffset = 0.0f;
    bool mollerTrumbore = false;
    // Tiles whose camera rays provably miss everything get a variant with no geometry
    // (render/traced_tiles.h); off only to measure what that saves (prism-bench no-cull).
    bool cullMissTiles = true;
    // Tiles whose camera rays can hit only planes, and whose shadow rays cannot reach the grid,
    // get a variant with no grid (render/plane_shadows.h), where nothing there starts a
    // secondary ray; off only to measure what that saves (prism-bench no-plane-tiles).
    bool cullPlaneTiles = true;
    // A camera ray's grid walk starts where its tile's rays may first meet the geometry
    // (render/traced_tiles.h, tileStartDistances) instead of where they enter the grid; off
    // only to measure what that saves (prism-bench no-tile-starts). Needs cullMissTiles.
    bool tileStarts = true;
    // At most this many start blocks (render/traced_tiles.h, kMaxStartBoxes): every frame projects
    // each on the host. Other values only to measure the trade (prism-bench start-boxes=N).
    size_t maxStartBoxes = kMaxStartBoxes;
    // The scene's extent found already, sceneExtent(scene, grid, kMaxStartBoxes) of the scene and
    // grid the tracer is made with (PreparedScene::extent, read from the cache where it was
    // kept): the constructor copies it instead of finding it again. Null, or another
    // maxStartBoxes than kMaxStartBoxes: found there.
    const SceneExtent *extent = nullptr;
    // On lavapipe, each thread's share of a dispatch takes every n-th row in order (n threads:
    // render/traced_tiles.h, spreadRowOrder); off: rows in bit-reversed order, as for a device
    // whose scheduling is unknown (prism-bench variant bit-reversed-rows).
    bool rowsByThread = true;
    // Grids of one kind: each cell entry's primitive stored in list order, so a test fetches no
    // primitive id first (triangles: GpuCellTriangle, 48 bytes an entry; spheres: centre and
    // radius, 16 bytes); off only to measure what that saves (prism-bench no-cell-primitives).
    bool cellPrimitives = true;
    // Scene arrays through a staging buffer even where the device shares the host's memory
    // (render/scene_buffers.h, UploadPath); only for the test that compares the two.
    bool stagedUpload = false;
    // The image read back through a copy to a buffer even on a CPU device, where the host
    // otherwise reads the accumulation in place (RayTracer::readback); only for the test that
    // compares the two.
    bool copiedReadback = false;
    // Finite primitives from which the tracer's pipeline compiles on one core while the scene's
    // arrays are written and its extent found on the other (RayTracer::compileBeside): below,
    // one after the other, as the arrays take less than the hand-over. Tests set 0 to compare.
    uint64_t compileBesideUploadFrom = 100'000;
    // The specialization folded into the tracer's modules on the host before the driver
    // translates them (vk/spirv_specialize.h): its pipelines are made in a third to half the
    // time. Off only to measure that (prism-bench no-fold) and for the test that compares.
    bool foldSpecialization = true;
};

struct TracerFeatures {
    uint32_t kinds = 0; // bit k: the scene has primitives of kind k (shared/primitive_kinds.h)
    bool reflection = false;
    bool transmission = false;
    bool textures = false;
    bool areaLights = false;
    bool vertexNormals = false;
    bool surfaceMaps = false; // normal or bump maps
    bool environment = false;
    bool shadows = true;
    bool writeAov = false;
    uint32_t maxDepth = 5;
    bool texelBuffers = false;     // arrays with texel views read through them
    bool adaptiveGrid = false;     // the grid is adaptive (accel/grid.h)
    uint32_t profile = 0;          // TracerOptions::profile
    bool resumable = false;        // loop budget and resumption (shaders/resume.glsl)
    uint32_t resumeLaneBudget = 0; // TracerOptions::resumeLaneBudget
    float fixedRayOffset = 0.0f;   // TracerOptions::fixedRayOffset
    bool mollerTrumbore = false;   // TracerOptions::mollerTrumbore
    bool cellTriangles = false;    // the cell triangle array is packed and walked
    bool cellSpheres = false;      // the cell sphere array is packed and walked

    bool has(uint32_t kind) const { return (kinds >> kind) & 1u; }
    bool operator==(const TracerFeatures &) const = default;
    // The same tracer for rays that hit nothing: no primitive kind and nothing that only a hit
    // uses; misses still see the environment, and AOVs are still written.
    TracerFeatures backgroundOnly() const;
    // The same tracer for tiles whose rays meet only planes and whose secondary rays, if any,
    // miss the grid: no grid, no finite kind, no refraction, and no reflection unless
    // `reflections` (a mirror plane's; render/traced_tiles.h, tileClasses).
    TracerFeatures planesOnly(bool reflections) const;
    std::vector<vk::SpecializationConstant> specialization() const;
};

// What the scene's content asks for (options at their defaults).
TracerFeatures featuresOf(const Scene &scene);

// The variant to compile: the scene's features with the caller's options applied.
// Cell triangles (spheres) are used where the scene's finite primitives are all triangles
// (spheres), arrays are read as texels, and the array fits in maxTexelElements texels (else the
// cells keep their ids).
// Throws prism::Error for a depth outside 1..64.
TracerFeatures chooseFeatures(const Scene &scene, const Grid &grid, const TracerOptions &options,
                              uint64_t maxTexelElements = UINT64_MAX);

} // namespace prism
