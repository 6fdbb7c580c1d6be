#include "scene/obj_loader.h"

#include "core/error.h"
#include "core/huge_pages.h"
#include "scene/diagnostics.h"
#include "scene/number_parser.h"
#include "scene/tokenizer.h"

#include <algorithm>
#include <cstring>

namespace prism {
namespace {

float objNumber(std::string_view word) {
    ParsedFloat parsed = parseFloat(word);
    if (!parsed.ok())
        throw LineError(describeBadNumber(word, parsed.problem));
    return parsed.value;
}

// The first `need` numbers after the keyword are required; up to N are read; more are
// ignored (a vertex's w or colour, a texture coordinate's w).
template <int N>
glm::vec<N, float> objVector(const std::vector<std::string_view> &words, int need,
                             const char *what) {
    int given = int(words.size()) - 1;
    if (given < need)
        throw LineError(std::string(what) + " needs " + std::to_string(need) +
                        (need == 1 ? " number" : " numbers") + ", got " + std::to_string(given));
    glm::vec<N, float> result(0.0f);
    for (int i = 0; i < N && i < given; ++i)
        result[i] = objNumber(words[i + 1]);
    return result;
}

// Where the reader is: the file and line for messages, and which warnings were given.
struct ObjContext {
    const std::string &fileName;
    int line = 0;
    bool warnedUv = false, warnedNormal = false, warnedSmoothing = false;
    uint32_t smoothingGroup = 0; // the last `s` statement's
};

std::string rangeMessage(const char *what, int64_t value, size_t count, const char *plural) {
    return "face " + std::string(what) + "index " + std::to_string(value) + " is out of range (" +
           std::to_string(count) + " " + plural + " defined so far)";
}

// OBJ index (1-based, or negative relative to the count so far) to a 0-based index, or
// kObjNoIndex when out of range (`value`: the index as written). `what` names the kind in
// messages: "" (vertex), "texture coordinate " or "normal ".
int32_t resolveIndex(std::string_view text, size_t count, const char *what, int64_t &value) {
    ParsedInteger parsed = parseInteger(text);
    if (!parsed.ok())
        throw LineError("bad face " + std::string(what) + "index '" + std::string(text) + "'");
    value = parsed.value;
    int64_t index = parsed.value > 0 ? parsed.value - 1 : int64_t(count) + parsed.value;
    if (parsed.value == 0 || index < 0 || index >= int64_t(count))
        return kObjNoIndex;
    return int32_t(index);
}

// A texture coordinate or normal: out of range, the corner goes without it (warned once).
int32_t optionalIndex(std::string_view text, size_t count, const char *what, const char *plural,
                      bool &warned, ObjContext &context, ObjModel &model) {
    int64_t value = 0;
    int32_t index = resolveIndex(text, count, what, value);
    if (value == 0) // not a reference at all: malformed, as for a vertex
        throw LineError(rangeMessage(what, value, count, plural));
    if (index == kObjNoIndex && !warned) {
        warned = true;
        model.warnings.push_back(warningAt(context.fileName, context.line,
                                           rangeMessage(what, value, count, plural) +
                                               "; such corners go without (warned once)"));
    }
    return index;
}

ObjCorner parseCorner(std::string_view word, ObjContext &context, ObjModel &model) {
    std::string_view parts[3];
    int partCount = 0;
    for (size_t start = 0;;) {
        size_t slash = word.find('/', start);
        if (partCount == 3)
            throw LineError("bad face corner '" + std::string(word) + "'");
        parts[partCount++] = word.substr(start, slash - start); // npos - start: to the end
        if (slash == std::string_view::npos)
            break;
        start = slash + 1;
    }
    // v, v/vt, v//vn, v/vt/vn: the position is required, an empty vt means none.
    if (parts[0].empty() || (partCount == 2 && parts[1].empty()) ||
        (partCount == 3 && parts[2].empty()))
        throw LineError("bad face corner '" + std::string(word) + "'");
    ObjCorner corner;
    int64_t value = 0;
    corner.position = resolveIndex(parts[0], model.positions.size(), "", value);
    if (corner.position == kObjNoIndex) // a position is geometry: no way round it
        throw LineError(rangeMessage("", value, model.positions.size(), "vertices"));
    if (partCount >= 2 && !parts[1].empty())
        corner.uv = optionalIndex(parts[1], model.uvs.size(), "texture coordinate ",
                                  "texture coordinates", context.warnedUv, context, model);
    if (partCount == 3)
        corner.normal = optionalIndex(parts[2], model.normals.size(), "normal ", "normals",
                                      context.warnedNormal, context, model);
    return corner;
}

void parseFace(const std::vector<std::string_view> &words, ObjContext &context, ObjModel &model) {
    size_t cornerCount = words.size() - 1;
    if (cornerCount < 3)
        throw LineError("a face needs at least 3 vertices, got " + std::to_string(cornerCount));
    ObjFace face;
    face.firstCorner = uint32_t(model.corners.size());
    face.cornerCount = uint32_t(cornerCount);
    face.materialSlot = model.useMtl.empty() ? kObjNoIndex : int32_t(model.useMtl.size() - 1);
    face.smoothingGroup = context.smoothingGroup;
    face.line = context.line;
    for (size_t i = 1; i < words.size(); ++i)
        model.corners.push_back(parseCorner(words[i], context, model));
    model.faces.push_back(face);
}

// `s N` or `s off` (= `s 0`): faces below share vertex normals only within their group when a
// mesh is smoothed. A value that is neither is not worth refusing a file for: group 0.
void parseSmoothingGroup(const std::vector<std::string_view> &words, ObjContext &context,
                         ObjModel &model) {
    context.smoothingGroup = 0;
    if (words.size() >= 2 && words[1] == "off")
        return;
    ParsedInteger group =
        words.size() >= 2 ? parseInteger(words[1]) : ParsedInteger{0, NumberProblem::NotANumber};
    if (group.ok() && group.value >= 0 && group.value <= int64_t(UINT32_MAX)) {
        context.smoothingGroup = uint32_t(group.value);
    } else if (!context.warnedSmoothing) {
        context.warnedSmoothing = true;
        model.warnings.push_back(
            warningAt(context.fileName, context.line,
                      "smoothing group must be a number or 'off'; taken as off (warned once)"));
    }
}

void parseStatement(std::string_view text, const std::vector<std::string_view> &words,
                    ObjContext &context, ObjModel &model) {
    int line = context.line;
    std::string_view keyword = words[0];
    if (keyword == "v") {
        model.positions.push_back(objVector<3>(words, 3, "a vertex"));
    } else if (keyword == "vt") {
        model.uvs.push_back(objVector<2>(words, 1, "a texture coordinate"));
    } else if (keyword == "vn") {
        model.normals.push_back(objVector<3>(words, 3, "a normal"));
    } else if (keyword == "f") {
        parseFace(words, context, model);
    } else if (keyword == "s") {
        parseSmoothingGroup(words, context, model);
    } else if (keyword == "usemtl") {
        model.useMtl.push_back(ObjUseMtl{std::string(restAfterFirstWord(text)), line});
    } else if (keyword == "mtllib") {
        std::string path(restAfterFirstWord(text));
        std::replace(path.begin(), path.end(), '\\', '/');
        if (path.empty())
            throw LineError("mtllib needs a file name");
        model.mtlLibs.push_back(ObjMtlLib{std::move(path), line});
    }
    // Everything else (o, g, l, p, vp, cstype, ...) is of no use to a ray tracer.
}

// How many of each element the text holds, counted from the lines' first words (a face's
// corners: the words after `f`), so that the arrays are sized once and in huge pages: growing
// them cost a copy and a page fault per 4 KiB of a million-triangle file (issue 31). Counts
// are upper bounds of a sort only; the parser still checks every line.
void reserveFor(std::string_view text, ObjModel &model) {
    size_t positions = 0, uvs = 0, normals = 0, faces = 0, corners = 0;
    const char *p = text.data(), *end = p + text.size();
    while (p < end) {
        const char *lineEnd = static_cast<const char *>(std::memchr(p, '\n', size_t(end - p)));
        if (!lineEnd)
            lineEnd = end;
        while (p < lineEnd && isBlank(*p))
            ++p;
        if (lineEnd - p >= 2 && p[0] == 'v' && isBlank(p[1]))
            ++positions;
        else if (lineEnd - p >= 3 && p[0] == 'v' && p[1] == 't' && isBlank(p[2]))
            ++uvs;
        else if (lineEnd - p >= 3 && p[0] == 'v' && p[1] == 'n' && isBlank(p[2]))
            ++normals;
        else if (lineEnd - p >= 2 && p[0] == 'f' && isBlank(p[1])) {
            ++faces;
            for (const char *q = p + 1; q < lineEnd; ++q)
                corners += isBlank(q[-1]) && !isBlank(q[0]);
        }
        p = lineEnd + 1;
    }
    reserveInHugePages(model.positions, positions);
    reserveInHugePages(model.uvs, uvs);
    reserveInHugePages(model.normals, normals);
    reserveInHugePages(model.faces, faces);
    reserveInHugePages(model.corners, corners);
}

} // namespace

ObjModel copyModel(const ObjModelView &v) {
    return {{v.positions.begin(), v.positions.end()}, {v.uvs.begin(), v.uvs.end()},
            {v.normals.begin(), v.normals.end()},     {v.corners.begin(), v.corners.end()},
            {v.faces.begin(), v.faces.end()},         {v.useMtl.begin(), v.useMtl.end()},
            {v.mtlLibs.begin(), v.mtlLibs.end()},     {v.warnings.begin(), v.warnings.end()}};
}

ObjModel parseObj(std::string_view text, const std::string &fileName) {
    ObjModel model;
    reserveFor(text, model);
    ObjContext context{fileName};
    LineCursor lines(text);
    std::string_view line;
    std::vector<std::string_view> words;
    while (lines.next(line)) {
        splitWords(line, words);
        if (words.empty())
            continue;
        try {
            context.line = lines.lineNumber();
            parseStatement(line, words, context, model);
        } catch (const LineError &e) {
            throw FileError(fileName, lines.lineNumber(), e.what());
        }
    }
    return model;
}

} // namespace prism
