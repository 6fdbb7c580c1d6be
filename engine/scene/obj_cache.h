#pragma once
// Parsed OBJ files kept in the disk cache (cache/disk_cache.h), so that loading a big mesh
// again digests its file instead of parsing it: parsing a 41 MB, 1M-triangle OBJ took 186-221
// ms, digesting it and reading the parsed arrays back about a quarter of that (issue 31,
// docs/benchmarks.md "The parsed-OBJ cache").
//
// The key is a digest of the file's bytes, the name it is shown by (the model's warnings name
// it), the entry format and the parser's own sources (so a changed parser never meets an old
// model). An entry that passes the cache's checksum but does not make a consistent model (an
// index past its array) is removed with one warning line and the file parsed anew.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "cache/disk_cache.h"
#include "scene/obj_loader.h"

namespace prism {

constexpr uint32_t kObjCacheFormat = 1;

// Files smaller than this are parsed every time: a 1 MiB OBJ parses in about 5 ms, and each
// cached file is one more entry in the cache's directory.
constexpr uint64_t kMinCachedObjBytes = uint64_t(1) << 20;

// Where a scene's OBJ files come from, and what that cost, for --stats.
struct ObjCacheUse {
    const DiskCache *cache = nullptr; // none: every file is parsed
    uint64_t minBytes = kMinCachedObjBytes;
    int hits = 0, misses = 0; // cached files read back, and parsed then stored
    double keyMs = 0.0;       // digesting the files
    double readMs = 0.0;      // reading entries back (hits)
    double storeMs = 0.0;     // packing and writing them (misses)
};

std::string objCacheKey(std::string_view fileBytes, const std::string &fileName);
std::string packObjModel(const ObjModel &model);
// The model packed in `bytes`, its arrays viewed in `bytes` where they lie aligned (else
// copied into `rest`), its usemtl and mtllib lines and warnings always in `rest`: the view
// lives as long as both. Throws BlobFormatError on a damaged entry.
ObjModelView viewObjModel(std::string_view bytes, ObjModel &rest);
ObjModel unpackObjModel(std::string_view bytes); // viewObjModel, copied

// A model as loadObjFile gives it: parsed (its own arrays), or read back from the cache, its
// arrays viewed in the entry's mapped bytes: the page cache's own pages, where a copy made
// 60 MB of fresh memory for a 1M-triangle mesh (core/mapped_file.h). Movable: the arrays
// viewed stay where they are.
class LoadedObjModel {
public:
    explicit LoadedObjModel(ObjModel parsed);
    explicit LoadedObjModel(CacheEntry entry); // throws BlobFormatError on a damaged entry
    const ObjModelView &view() const { return view_; }

private:
    ObjModel owned_;
    std::optional<CacheEntry> entry_;
    ObjModelView view_;
};

// parseObj of the file at `path` (shown as `fileName`), through the cache when `use` has one
// and the file is at least use->minBytes long. Same errors as parseObj, and prism::Error when
// the file cannot be read.
LoadedObjModel loadObjFile(const std::filesystem::path &path, const std::string &fileName,
                           ObjCacheUse *use);

} // namespace prism
