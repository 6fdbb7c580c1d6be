#pragma once
// A content-addressed store on disk for what is slow to make and quick to read back: built
// grids (accel/grid_cache.h). An entry is a file `KIND-KEY.bin` in the cache directory: a
// header (magic, format version, payload size and checksum, the key again) and the payload.
//
// - Written atomically (a temporary file in the same directory, then rename), so a reader
//   never sees half an entry and two processes filling the same entry leave one whole one.
// - Checked on every read: an entry whose size, checksum, key or format does not match is
//   removed with one warning line, and the caller makes the thing anew; it never crashes on
//   one and never hands back its bytes.
// - Bounded: after each write the least recently used entries (file times, touched on every
//   hit) are removed until the directory holds at most maxBytes.
// - Best effort: a directory that cannot be made or written costs a warning, never a render.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/mapped_file.h"

namespace prism {

struct DiskCacheOptions {
    std::filesystem::path directory;
    uint64_t maxBytes = uint64_t(4) << 30;
    // Where warnings go (one line each, no newline); stderr when empty.
    std::function<void(const std::string &)> warn;
};

// An entry's payload, checked, as the file's mapped bytes (no copy: a grid's 73 MB entry is read
// straight from the page cache into its arrays). Entries are only ever replaced by renaming a
// new file over them and trimmed by unlinking, so a mapped entry never changes under its reader.
struct CacheEntry {
    std::unique_ptr<MappedFile> file;
    std::string_view payload;
};

class DiskCache {
public:
    explicit DiskCache(DiskCacheOptions options);

    // $PRISM_CACHE_DIR, else $XDG_CACHE_HOME/prism, else $HOME/.cache/prism; empty when none
    // of them is set.
    static std::filesystem::path defaultDirectory();

    // The payload stored under (kind, key) by a writer of `format`, or nothing: absent, or
    // damaged or stale (then removed, with a warning).
    std::optional<CacheEntry> load(std::string_view kind, std::string_view key,
                                   uint32_t format) const;
    // Removes the entry under (kind, key) with one warning line: for a caller whose entry passed
    // the checks above but does not make the thing it stored (`why`); the caller makes it anew.
    void discard(std::string_view kind, std::string_view key, const std::string &why) const;
    // Stores `payload` under (kind, key), then trims the cache to its size. Never throws.
    void store(std::string_view kind, std::string_view key, uint32_t format,
               std::string_view payload) const;
    // The same, the payload the pieces' bytes one after the other (cache/blob.h, BlobWriter):
    // written as they lie, never gathered into one copy.
    void store(std::string_view kind, std::string_view key, uint32_t format,
               std::span<const std::string_view> pieces) const;

    const std::filesystem::path &directory() const { return options_.directory; }
    std::filesystem::path entryPath(std::string_view kind, std::string_view key) const;

private:
    void warn(const std::string &message) const;
    void trim(const std::filesystem::path &keep) const;

    DiskCacheOptions options_;
    // A directory that cannot be written is said once: a run stores several entries.
    mutable std::atomic<bool> saidUnwritable_{false};
};

} // namespace prism
