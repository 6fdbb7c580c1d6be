#include "scene/scene_parser.h"

#include "core/error.h"
#include "scene/diagnostics.h"
#include "scene/text_file.h"

namespace prism {

void SceneBuilder::warn(const std::string &message) {
    scene.warnings.push_back(warningAt(fileName, line, message));
}

Scene parseSceneText(std::string_view text, const std::filesystem::path &virtualPath,
                     const SceneLimits &limits, ObjCacheUse *objCache) {
    SceneBuilder builder;
    builder.limits = limits;
    builder.objCache = objCache;
    builder.fileName = virtualPath.generic_string();
    builder.baseDir = virtualPath.parent_path();
    builder.scene.materials.push_back(Material{"default"});
    builder.materialByName["default"] = 0;
    builder.materialLine["default"] = 0;

    LineCursor lines(text);
    std::string_view line;
    std::vector<Token> tokens;
    std::string lexError;
    while (lines.next(line)) {
        builder.line = lines.lineNumber();
        try {
            if (!tokenizeSceneLine(line, tokens, lexError))
                throw LineError(lexError);
            if (!tokens.empty())
                applyDirective(builder, tokens);
        } catch (const FileError &) {
            throw; // already names its file and line (an OBJ or MTL error)
        } catch (const LineError &e) {
            throw FileError(builder.fileName, builder.line, e.what());
        } catch (const Error &e) {
            throw FileError(builder.fileName, builder.line, e.what());
        }
    }
    return std::move(builder.scene);
}

} // namespace prism
