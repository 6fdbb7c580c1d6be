#include "scene/obj_cache.h"

#include <optional>

#include "cache/blob.h"
#include "cache/content_hash.h"
#include "cache/disk_cache.h"
#include "core/mapped_file.h"
#include "core/timer.h"
#include "scene/obj_source_digest.h"

namespace prism {
namespace {

// Entries hold the arrays' bytes as they are: no padding in them, so none of their bytes is
// left unset (the checksum reads every byte).
static_assert(sizeof(ObjCorner) == 12 && sizeof(ObjFace) == 20);

// Strings with their OBJ lines (usemtl, mtllib), and warnings.
template <typename Named> void packNamed(BlobWriter &out, const std::vector<Named> &list) {
    out.value(uint64_t(list.size()));
    for (const Named &n : list) {
        if constexpr (std::is_same_v<Named, ObjUseMtl>)
            out.text(n.name);
        else
            out.text(n.path);
        out.value(int32_t(n.line));
    }
}

template <typename Named> std::vector<Named> unpackNamed(BlobReader &in) {
    uint64_t count = in.value<uint64_t>();
    std::vector<Named> list;
    for (uint64_t i = 0; i < count; ++i) {
        std::string text = in.text();
        list.push_back(Named{std::move(text), int(in.value<int32_t>())});
    }
    return list;
}

bool inRange(int32_t index, size_t count) {
    return index >= 0 && size_t(index) < count;
}

// The importer indexes the arrays with what the model says, unchecked: an entry that passed the
// checksum but holds an index past its array (a writer's bug) must not get there.
void checkIndices(const ObjModelView &m) {
    for (const ObjCorner &c : m.corners) {
        if (!inRange(c.position, m.positions.size()) ||
            (c.uv != kObjNoIndex && !inRange(c.uv, m.uvs.size())) ||
            (c.normal != kObjNoIndex && !inRange(c.normal, m.normals.size())))
            throw BlobFormatError("a corner's index is past its array");
    }
    for (const ObjFace &f : m.faces) {
        if (f.cornerCount < 3 || f.firstCorner > m.corners.size() ||
            f.cornerCount > m.corners.size() - f.firstCorner)
            throw BlobFormatError("a face's corners are past the corner array");
        if (f.materialSlot != kObjNoIndex && !inRange(f.materialSlot, m.useMtl.size()))
            throw BlobFormatError("a face's usemtl is past the usemtl list");
    }
}

// The model's entry, its arrays borrowed from it.
BlobWriter objRecord(const ObjModel &model) {
    BlobWriter out;
    out.values(model.positions);
    out.values(model.uvs);
    out.values(model.normals);
    out.values(model.corners);
    out.values(model.faces);
    packNamed(out, model.useMtl);
    packNamed(out, model.mtlLibs);
    out.value(uint64_t(model.warnings.size()));
    for (const std::string &w : model.warnings)
        out.text(w);
    return out;
}

ObjModel parseAndStore(std::string_view bytes, const std::string &fileName, const std::string &key,
                       ObjCacheUse &use) {
    ObjModel model = parseObj(bytes, fileName); // a file with errors throws: nothing stored
    Timer timer;
    use.cache->store("obj", key, kObjCacheFormat, objRecord(model).pieces());
    use.storeMs += timer.elapsedMs();
    ++use.misses;
    return model;
}

} // namespace

std::string objCacheKey(std::string_view fileBytes, const std::string &fileName) {
    ContentHash hash;
    hash.text("prism obj").text(PRISM_OBJ_SOURCE_DIGEST).value(kObjCacheFormat);
    hash.text(fileName); // the warnings name the file
    hash.text(fileBytes);
    return hash.hex();
}

std::string packObjModel(const ObjModel &model) {
    return objRecord(model).take();
}

ObjModelView viewObjModel(std::string_view bytes, ObjModel &rest) {
    BlobReader in(bytes);
    ObjModelView view;
    view.positions = in.view(rest.positions);
    view.uvs = in.view(rest.uvs);
    view.normals = in.view(rest.normals);
    view.corners = in.view(rest.corners);
    view.faces = in.view(rest.faces);
    rest.useMtl = unpackNamed<ObjUseMtl>(in);
    rest.mtlLibs = unpackNamed<ObjMtlLib>(in);
    uint64_t warnings = in.value<uint64_t>();
    for (uint64_t i = 0; i < warnings; ++i)
        rest.warnings.push_back(in.text());
    if (!in.atEnd())
        throw BlobFormatError("bytes left over after the model");
    view.useMtl = rest.useMtl;
    view.mtlLibs = rest.mtlLibs;
    view.warnings = rest.warnings;
    checkIndices(view);
    return view;
}

ObjModel unpackObjModel(std::string_view bytes) {
    ObjModel rest;
    return copyModel(viewObjModel(bytes, rest));
}

LoadedObjModel::LoadedObjModel(ObjModel parsed) : owned_(std::move(parsed)), view_(owned_.view()) {}

LoadedObjModel::LoadedObjModel(CacheEntry entry) : entry_(std::move(entry)) {
    view_ = viewObjModel(entry_->payload, owned_);
}

LoadedObjModel loadObjFile(const std::filesystem::path &path, const std::string &fileName,
                           ObjCacheUse *use) {
    // Mapped, not copied: the page cache's pages cost no fresh memory (core/mapped_file.h).
    MappedFile file(path, "OBJ file");
    std::string_view bytes = file.bytes();
    if (!use || !use->cache || bytes.size() < use->minBytes)
        return LoadedObjModel(parseObj(bytes, fileName));
    Timer timer;
    std::string key = objCacheKey(bytes, fileName);
    use->keyMs += timer.elapsedMs();
    timer.reset();
    if (std::optional<CacheEntry> entry = use->cache->load("obj", key, kObjCacheFormat)) {
        try {
            LoadedObjModel model(std::move(*entry));
            use->readMs += timer.elapsedMs();
            ++use->hits;
            return model;
        } catch (const BlobFormatError &e) {
            use->cache->discard("obj", key, "parsed from '" + fileName + "': " + e.what());
        }
    }
    return LoadedObjModel(parseAndStore(bytes, fileName, key, *use));
}

} // namespace prism
