#include "cache_option.h"

#include "cache/disk_cache.h"
#include "core/error.h"

namespace prism {

std::filesystem::path CacheOption::resolve() const {
    if (off && !directory.empty())
        throw Error("--cache and --no-cache cannot be given together");
    if (off)
        return {};
    return directory.empty() ? DiskCache::defaultDirectory() : std::filesystem::path(directory);
}

void addCacheOptions(CLI::App &app, CacheOption &option) {
    app.add_option("--cache", option.directory,
                   "Keep built grids, OBJ files of 1 MiB or more as parsed, and the tracer as "
                   "specialized for the scene in this directory and reuse them (default: "
                   "$PRISM_CACHE_DIR, else $XDG_CACHE_HOME/prism, else ~/.cache/prism)");
    app.add_flag("--no-cache", option.off,
                 "Build the grid and parse the OBJ files without reading or writing the cache");
}

} // namespace prism
