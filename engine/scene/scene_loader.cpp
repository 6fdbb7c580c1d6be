#include "scene/scene_loader.h"

#include "scene/scene_parser.h"
#include "scene/text_file.h"

namespace prism {

Scene loadScene(const std::filesystem::path &path, const SceneLimits &limits,
                ObjCacheUse *objCache) {
    return parseSceneText(readTextFile(path, "scene file"), path, limits, objCache);
}

Scene parseScene(std::string_view text, const std::filesystem::path &virtualPath,
                 const SceneLimits &limits, ObjCacheUse *objCache) {
    return parseSceneText(text, virtualPath, limits, objCache);
}

} // namespace prism
