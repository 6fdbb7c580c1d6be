#pragma once
// A scene made ready to be rendered many times, as every front end does it (prism-render, its
// frame ranges and farm tasks, the Python module): centred on its frame-1 camera
// (scene/scene_origin.h) and its grid built, or read from the grid cache (accel/grid_cache.h).
// Cameras given later (an animation's frames, a camera set from Python) are moved into the same
// coordinates with toSceneCoordinates.
#include "accel/grid.h"
#include "accel/grid_cache.h"
#include "scene/scene.h"

namespace prism {

class DiskCache;

struct PreparedScene {
    Scene scene; // centred: Scene::origin holds the shift from the file's coordinates
    Grid grid;
    GridCacheOutcome gridCache;
    double buildMs = 0.0; // the grid's build or cache read
};

// `cache` may be null (no grid cache).
PreparedScene prepareScene(Scene scene, const GridOptions &options, const DiskCache *cache);

// A camera in the file's coordinates, moved to the prepared scene's.
Camera toSceneCoordinates(const PreparedScene &prepared, Camera camera);

} // namespace prism
