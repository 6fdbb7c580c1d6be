#pragma once
// The figures a render reports, under one set of names for every front end: prism-render
// --stats prints them as a JSON line, the Python module's Renderer.last_stats returns them as a
// dict. Each function gives one group of keys; the front ends add their own timings.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accel/grid.h"
#include "render/ray_tracer.h"
#include "render/scene_buffers.h"
#include "scene/obj_cache.h"
#include "session/prepared_scene.h"

namespace prism {

// A regular grid's resolution "48x12x40", or "adaptive 13x5x13 top, 81234 cells, depth 3".
std::string gridText(const Grid &grid);

// The scene and its grid: primitives, grid, grid_cells, grid_bytes, grid_mean_per_cell,
// grid_max_per_cell, grid_choice, triangles {scene, prototypes, instances, placed}, build_ms and
// grid_cache {state, key_ms, read_ms, store_ms}.
nlohmann::json sceneStats(const PreparedScene &prepared);

// Where the scene's OBJ files came from (scene/obj_cache.h): obj_cache {hits, misses, key_ms,
// read_ms, store_ms}.
nlohmann::json objCacheStats(const ObjCacheUse &use);

// One traced frame: rays {primary, shadow, secondary}, mrays_per_s (over `traceMs`) and
// resume_dispatches.
nlohmann::json frameStats(const RayCounts &rays, double traceMs, uint32_t resumeDispatches);

// Which tracer ran the frame's 8x8 tiles (FrameResult::tiles): {full, planes_only, background}.
nlohmann::json tileStats(const std::array<uint32_t, 3> &tiles);

// The scene's arrays on the device, by name, and their total (scene_gpu_bytes).
nlohmann::json gpuBytesStats(const std::vector<ArrayBytes> &arrays);

} // namespace prism
