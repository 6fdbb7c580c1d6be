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
#include <string>
#include <string_view>

#include "scene/obj_loader.h"

namespace prism {

class DiskCache;

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
ObjModel unpackObjModel(std::string_view bytes); // throws BlobFormatError on a damaged entry

// parseObj of the file at `path` (shown as `fileName`), through the cache when `use` has one
// and the file is at least use->minBytes long. Same errors as parseObj, and prism::Error when
// the file cannot be read.
ObjModel loadObjFile(const std::filesystem::path &path, const std::string &fileName,
                     ObjCacheUse *use);

} // namespace prism
