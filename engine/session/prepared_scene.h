#pragma once
// A scene made ready to be rendered many times, as every front end does it (prism-render, its
// frame ranges and farm tasks, the Python module): centred on its frame-1 camera
// (scene/scene_origin.h), its grid built, or read from the grid cache (accel/grid_cache.h),
// and its extent found, or read from the cache beside the grid (render/extent_cache.h).
// Cameras given later (an animation's frames, a camera set from Python) are moved into the same
// coordinates with toSceneCoordinates.
#include <optional>

#include "accel/grid.h"
#include "accel/grid_cache.h"
#include "render/extent_cache.h"
#include "scene/placement_animation.h"
#include "scene/scene.h"

namespace prism {

class DiskCache;

struct PreparedScene {
    Scene scene; // centred: Scene::origin holds the shift from the file's coordinates
    Grid grid;
    GridCacheOutcome gridCache;
    double buildMs = 0.0;    // the grid's build or cache read, and the extent's
    GridOptions gridOptions; // what the grid was built with
    // sceneExtent(scene, grid) with the tracer's default start-box cap, for the tracer
    // (TracerOptions::extent); none once moveToFrame has moved an instance (the tracer's
    // setScene finds its own).
    std::optional<SceneExtent> extent;
    ExtentCacheOutcome extentCache; // how it was found (kept when moveToFrame drops it)
    // The frame Scene::instances and the grid hold: 1 until moveToFrame moves keyed instances.
    double frame = 1.0;
};

// `cache` may be null (no grid cache).
PreparedScene prepareScene(Scene scene, const GridOptions &options, const DiskCache *cache);

// Moves the keyed instances (scene/placement_animation.h) to `frame` and builds the grid's level
// they are in again, the prototypes' mesh grids kept (Grid::meshGrids); the extent is dropped.
// Returns whether any instance moved, and so whether a tracer of the scene needs the new arrays
// (RayTracer::setScene); a scene without keyed placements, or a frame where none has moved
// (held before the first key and after the last), costs nothing. `rebuildMs`, where given,
// gets the build's time. Throws prism::Error as placementAt does.
bool moveToFrame(PreparedScene &prepared, double frame, double *rebuildMs = nullptr);

// A camera in the file's coordinates, moved to the prepared scene's.
Camera toSceneCoordinates(const PreparedScene &prepared, Camera camera);

} // namespace prism
