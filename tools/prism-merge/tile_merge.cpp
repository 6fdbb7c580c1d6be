#include "tile_merge.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "io/image_reader.h"

namespace prism {
namespace {

// Which channels of a tile hold what: the layouts prism-render writes.
struct ChannelLayout {
    bool depth = false, normal = false;
};

ChannelLayout layoutOf(const std::filesystem::path &path, const LoadedImage &tile) {
    const std::vector<std::string> &names = tile.channelNames;
    auto has = [&](const char *name) {
        return std::find(names.begin(), names.end(), name) != names.end();
    };
    ChannelLayout layout{has("Z"), has("N.X")};
    std::vector<std::string> expected = {"R", "G", "B", "A"};
    if (layout.depth)
        expected.push_back("Z");
    if (layout.normal)
        expected.insert(expected.end(), {"N.X", "N.Y", "N.Z"});
    if (names != expected) {
        std::string list;
        for (const std::string &n : names)
            list += (list.empty() ? "" : ",") + n;
        throw Error(path.string() + ": channels " + list +
                    " are not a prism-render image's (R,G,B,A, then Z and N.X,N.Y,N.Z)");
    }
    return layout;
}

std::string placeText(const LoadedImage &t) {
    return std::to_string(t.width) + "x" + std::to_string(t.height) + " at " +
           std::to_string(t.x) + "," + std::to_string(t.y);
}

// What a merged image's metadata keeps of the first tile's, and what it adds up.
ImageMetadata mergedMetadata(const std::vector<ImageMetadata> &tiles) {
    ImageMetadata out;
    uint64_t rays[3] = {0, 0, 0};
    const char *rayNames[3] = {"prism:raysPrimary", "prism:raysShadow", "prism:raysSecondary"};
    double traceMs = 0.0;
    for (const ImageMetadata &m : tiles) {
        for (const auto &[name, value] : m.strings)
            for (int k = 0; k < 3; ++k)
                if (name == rayNames[k])
                    rays[k] += std::stoull(value);
        for (const auto &[name, value] : m.floats)
            if (name == "prism:renderTimeMs")
                traceMs += value;
    }
    auto tileOnly = [](const std::string &name) {
        return name == "prism:region" || name == "prism:tile" || name == "prism:commandLine" ||
               name == "prism:renderTimeMs" || name == "prism:renderTimeMedianMs" ||
               name == "prism:mraysPerSecond" || name.rfind("prism:rays", 0) == 0 ||
               name.rfind("prism:", 0) != 0; // the file format's own (compression, dates)
    };
    for (const auto &s : tiles.front().strings)
        if (!tileOnly(s.first))
            out.strings.push_back(s);
    for (const auto &f : tiles.front().floats)
        if (!tileOnly(f.first))
            out.floats.push_back(f);
    for (const auto &i : tiles.front().ints)
        if (!tileOnly(i.first))
            out.ints.push_back(i);
    for (int k = 0; k < 3; ++k)
        out.strings.emplace_back(rayNames[k], std::to_string(rays[k]));
    out.floats.emplace_back("prism:renderTimeMs", float(traceMs));
    out.ints.emplace_back("prism:mergedTiles", int(tiles.size()));
    return out;
}

} // namespace

MergedImage mergeTiles(const std::vector<std::filesystem::path> &paths) {
    if (paths.empty())
        throw Error("no tiles to merge");
    MergedImage merged;
    OutputImage &whole = merged.image;
    std::vector<ImageMetadata> metadata;
    std::vector<int32_t> owner; // which tile holds each pixel (-1: none yet)
    ChannelLayout first;
    for (size_t t = 0; t < paths.size(); ++t) {
        const std::filesystem::path &path = paths[t];
        LoadedImage tile = readImage(path);
        ChannelLayout layout = layoutOf(path, tile);
        if (t == 0) {
            first = layout;
            whole.width = tile.fullWidth;
            whole.height = tile.fullHeight;
            size_t pixels = size_t(whole.width) * whole.height;
            whole.rgba.assign(pixels * 4, 0.0f);
            if (layout.depth)
                whole.depth.assign(pixels, 0.0f);
            if (layout.normal)
                whole.normal.assign(pixels * 3, 0.0f);
            owner.assign(pixels, -1);
        } else if (tile.fullWidth != whole.width || tile.fullHeight != whole.height) {
            throw Error(path.string() + ": a tile of a " + std::to_string(tile.fullWidth) + "x" +
                        std::to_string(tile.fullHeight) + " image, but " + paths[0].string() +
                        " is one of a " + std::to_string(whole.width) + "x" +
                        std::to_string(whole.height) + " image");
        } else if (layout.depth != first.depth || layout.normal != first.normal) {
            throw Error(path.string() + ": its channels differ from those of " +
                        paths[0].string());
        }
        if (tile.x < 0 || tile.y < 0 || tile.x + tile.width > whole.width ||
            tile.y + tile.height > whole.height)
            throw Error(path.string() + ": its pixels (" + placeText(tile) +
                        ") reach outside its " + std::to_string(whole.width) + "x" +
                        std::to_string(whole.height) + " image");
        int c = tile.channels;
        for (int y = 0; y < tile.height; ++y)
            for (int x = 0; x < tile.width; ++x) {
                size_t to = size_t(tile.y + y) * whole.width + size_t(tile.x + x);
                if (owner[to] >= 0)
                    throw Error(path.string() + ": pixel " + std::to_string(tile.x + x) + "," +
                                std::to_string(tile.y + y) + " is also in " +
                                paths[size_t(owner[to])].string() +
                                ": tiles of one split never overlap");
                owner[to] = int32_t(t);
                const float *from = &tile.pixels[(size_t(y) * tile.width + x) * size_t(c)];
                std::copy(from, from + 4, &whole.rgba[to * 4]);
                if (layout.depth)
                    whole.depth[to] = from[4];
                if (layout.normal)
                    std::copy(from + c - 3, from + c, &whole.normal[to * 3]);
            }
        metadata.push_back(tile.metadata);
    }
    auto gap = std::find(owner.begin(), owner.end(), -1);
    if (gap != owner.end()) {
        size_t at = size_t(gap - owner.begin());
        throw Error(std::to_string(std::count(owner.begin(), owner.end(), -1)) + " of the " +
                    std::to_string(whole.width) + "x" + std::to_string(whole.height) +
                    " image's pixels are in no tile given (the first: " +
                    std::to_string(at % size_t(whole.width)) + "," +
                    std::to_string(at / size_t(whole.width)) + "): is a tile missing?");
    }
    merged.metadata = mergedMetadata(metadata);
    return merged;
}

} // namespace prism
