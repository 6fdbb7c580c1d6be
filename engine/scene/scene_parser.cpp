#include "scene/scene_parser.h"

#include <algorithm>
#include <string_view>

#include "core/error.h"
#include "scene/diagnostics.h"
#include "scene/text_file.h"
#include "scene/tokenizer.h"

namespace prism {

void SceneBuilder::warn(const std::string &message) {
    scene.warnings.push_back(warningAt(fileName, line, message));
}

namespace {

// The lines of `text` whose first word is `f` or `triangle` (at least a triangle each), and
// those whose first word is `v`: the arrays are reserved for them before the parse. Grown a push
// at a time, a scene file of a million triangles had its 144 MB array copied and its fresh pages
// cleared at every doubling, a tenth of its load (docs/benchmarks.md). Faces of more corners
// make more triangles than counted: their array then grows as before. Only address space is
// reserved (pages are touched as triangles are written), capped by the scene's limit.
void reserveForGeometry(std::string_view text, SceneBuilder &builder) {
    size_t triangles = 0, vertices = 0;
    auto startsWithWord = [](std::string_view line, std::string_view word) {
        return line.size() > word.size() && line.substr(0, word.size()) == word &&
               isBlank(line[word.size()]);
    };
    LineCursor lines(text);
    for (std::string_view line; lines.next(line);) {
        line = trimBlanks(line);
        if (startsWithWord(line, "f") || startsWithWord(line, "triangle"))
            ++triangles;
        else if (startsWithWord(line, "v"))
            ++vertices;
    }
    builder.scene.triangles.reserve(
        size_t(std::min<uint64_t>(triangles, builder.limits.maxTriangles)));
    builder.faceVertices.reserve(vertices);
}

} // namespace

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

    reserveForGeometry(text, builder);
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
