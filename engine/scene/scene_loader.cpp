#include "scene/scene_loader.h"

#include "scene/scene_parser.h"
#include "scene/text_file.h"

namespace prism {

Scene loadScene(const std::filesystem::path &path) {
    return parseSceneText(readTextFile(path, "scene file"), path);
}

Scene parseScene(std::string_view text, const std::filesystem::path &virtualPath) {
    return parseSceneText(text, virtualPath);
}

} // namespace prism
