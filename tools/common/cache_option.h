#pragma once
// "--cache DIR" and "--no-cache": where prism-render and prism-view keep built grids and parsed
// OBJ files between runs (cache/disk_cache.h).
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

namespace prism {

struct CacheOption {
    std::string directory; // --cache, as given
    bool off = false;      // --no-cache
    // The directory to use: --cache's, else DiskCache::defaultDirectory(); empty with
    // --no-cache, or where no default can be found. Throws prism::Error when both were given.
    std::filesystem::path resolve() const;
};

// Adds both options to `app`, writing into `option`.
void addCacheOptions(CLI::App &app, CacheOption &option);

} // namespace prism
