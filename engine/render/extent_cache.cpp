#include "render/extent_cache.h"

#include <cmath>

#include "cache/blob.h"
#include "cache/content_hash.h"
#include "cache/disk_cache.h"
#include "core/timer.h"
#include "render/extent_source_digest.h"

namespace prism {
namespace {

constexpr const char *kKind = "extent";

// A box the tracer's tiles can use: finite, or the empty box's infinities, never NaN.
void checkBoxes(const std::vector<Aabb> &boxes) {
    for (const Aabb &box : boxes)
        for (int a = 0; a < 3; ++a)
            if (std::isnan(box.min[a]) || std::isnan(box.max[a]))
                throw BlobFormatError("a box with a NaN corner");
}

} // namespace

std::string extentCacheKey(const std::string &gridKey, size_t maxStartBoxes) {
    ContentHash hash;
    hash.text("prism extent").text(PRISM_EXTENT_SOURCE_DIGEST).value(kExtentCacheFormat);
    hash.text(gridKey).value(uint64_t(maxStartBoxes));
    return hash.hex();
}

std::string packExtent(const SceneExtent &extent) {
    BlobWriter out;
    out.values(extent.boxes);
    out.values(extent.planes);
    out.values(extent.startBoxes);
    return out.take();
}

SceneExtent unpackExtent(std::string_view bytes) {
    BlobReader in(bytes);
    SceneExtent extent;
    extent.boxes = in.values<Aabb>();
    extent.planes = in.values<glm::dvec4>();
    extent.startBoxes = in.values<Aabb>();
    if (!in.atEnd())
        throw BlobFormatError("bytes left over after the extent");
    checkBoxes(extent.boxes);
    checkBoxes(extent.startBoxes);
    return extent;
}

SceneExtent sceneExtentCached(const Scene &scene, const Grid &grid, size_t maxStartBoxes,
                              const DiskCache *cache, const std::string &gridKey,
                              ExtentCacheOutcome *outcome) {
    ExtentCacheOutcome local;
    ExtentCacheOutcome &o = outcome ? *outcome : local;
    Timer timer;
    if (!cache || gridKey.empty()) {
        o.state = "off";
        SceneExtent extent = sceneExtent(scene, grid, maxStartBoxes);
        o.ms = timer.elapsedMs();
        return extent;
    }
    std::string key = extentCacheKey(gridKey, maxStartBoxes);
    if (std::optional<CacheEntry> entry = cache->load(kKind, key, kExtentCacheFormat)) {
        try {
            SceneExtent extent = unpackExtent(entry->payload);
            o.state = "hit";
            o.ms = timer.elapsedMs();
            return extent;
        } catch (const BlobFormatError &e) {
            cache->discard(kKind, key, e.what());
        }
    }
    SceneExtent extent = sceneExtent(scene, grid, maxStartBoxes);
    cache->store(kKind, key, kExtentCacheFormat, packExtent(extent));
    o.state = "miss";
    o.ms = timer.elapsedMs();
    return extent;
}

} // namespace prism
