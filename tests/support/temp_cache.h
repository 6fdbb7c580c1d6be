#pragma once
// A disk cache in a directory of its own that keeps the warnings it gives, for the tests of
// what is kept in it (grids, extents).
#include <string>
#include <vector>

#include "cache/disk_cache.h"
#include "temp_dir.h"

namespace prism::test {

struct CacheInTempDir {
    TempDir dir;
    std::vector<std::string> warnings;
    DiskCache cache{DiskCacheOptions{dir.path(), uint64_t(1) << 30,
                                     [this](const std::string &w) { warnings.push_back(w); }}};
};

} // namespace prism::test
