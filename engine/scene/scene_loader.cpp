#include "scene/scene_loader.h"

#include "scene/scene_parser.h"
#include "scene/text_file.h"

namespace prism {

Scene loadScene(const std::filesystem::path &path, const SceneLimits &limits) {
    return parseSceneText(readTextFile(path, "scene file"), path, limits);
}

Scene parseScene(std::string_view text, const std::filesystem::path &virtualPath,
                 const SceneLimits &limits) {
    return parseSceneText(text, virtualPath, limits);
}

} // namespace prism
