#include "session/prepared_scene.h"

#include <utility>

#include "core/timer.h"
#include "scene/scene_origin.h"

namespace prism {

PreparedScene prepareScene(Scene scene, const GridOptions &options, const DiskCache *cache) {
    PreparedScene prepared;
    prepared.scene = std::move(scene);
    // An animation's frames are all relative to its frame-1 eye, so a frame is the same image
    // in any range (scene_origin.h).
    centerOnCamera(prepared.scene);
    Timer build;
    prepared.grid =
        buildGridCached(prepared.scene, options, GridCachePolicy{cache}, &prepared.gridCache);
    // Part of the build phase: what the grid's arrays come to on the image, found where
    // every core is free (the tracer's own set-up runs beside its compile on one).
    prepared.extent = sceneExtentCached(prepared.scene, prepared.grid, kMaxStartBoxes, cache,
                                        prepared.gridCache.key, &prepared.extentCache);
    prepared.buildMs = build.elapsedMs();
    prepared.gridOptions = options;
    return prepared;
}

bool moveToFrame(PreparedScene &prepared, double frame, double *rebuildMs) {
    if (rebuildMs)
        *rebuildMs = 0.0;
    if (!placementsAnimated(prepared.scene) || frame == prepared.frame)
        return false;
    std::vector<Instance> instances = instancesAt(prepared.scene, frame);
    prepared.frame = frame;
    if (instances == prepared.scene.instances)
        return false;
    Timer build;
    prepared.scene.instances = std::move(instances);
    prepared.grid =
        rebuildInstanceLevel(prepared.scene, std::move(prepared.grid), prepared.gridOptions);
    prepared.extent.reset();
    if (rebuildMs)
        *rebuildMs = build.elapsedMs();
    return true;
}

Camera toSceneCoordinates(const PreparedScene &prepared, Camera camera) {
    camera.eye -= prepared.scene.origin;
    camera.look -= prepared.scene.origin;
    return camera;
}

} // namespace prism
