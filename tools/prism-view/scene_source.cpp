#include "scene_source.h"

#include "scene/scene_loader.h"

namespace prism {

SceneSource::SceneSource(std::filesystem::path path) : path_(std::move(path)) {}

std::optional<std::filesystem::file_time_type> SceneSource::modificationTime() const {
    std::error_code error;
    auto time = std::filesystem::last_write_time(path_, error);
    if (error)
        return std::nullopt;
    return time;
}

Scene SceneSource::load(ObjCacheUse *objCache) {
    // Taken before reading: a save during the load is seen as a change next time.
    loadedTime_ = modificationTime();
    return loadScene(path_, {}, objCache);
}

bool SceneSource::changedOnDisk() {
    if (sinceCheck_.elapsedMs() < 500.0)
        return false;
    sinceCheck_.reset();
    auto now = modificationTime();
    if (!now || now == loadedTime_)
        return false;
    loadedTime_ = now;
    return true;
}

} // namespace prism
