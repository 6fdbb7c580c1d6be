#pragma once
// The scene file the viewer shows: loads it (F5) and notices when it changes on disk.
#include <filesystem>
#include <optional>

#include "core/timer.h"
#include "scene/obj_cache.h"
#include "scene/scene.h"

namespace prism {

class SceneSource {
public:
    explicit SceneSource(std::filesystem::path path);
    // Loads and parses the file, its big OBJ files through `objCache` where given
    // (scene/obj_cache.h); throws prism::FileError / prism::Error as loadScene does.
    Scene load(ObjCacheUse *objCache = nullptr);
    // True once after the file's modification time changes (checked every half second). A file
    // that is briefly missing (an editor saving by rename) does not count as a change.
    bool changedOnDisk();
    const std::filesystem::path &path() const { return path_; }

private:
    std::optional<std::filesystem::file_time_type> modificationTime() const;
    std::filesystem::path path_;
    std::optional<std::filesystem::file_time_type> loadedTime_;
    Timer sinceCheck_;
};

} // namespace prism
