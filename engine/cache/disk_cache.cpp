#include "cache/disk_cache.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "cache/content_hash.h"
#include "core/error.h"

namespace prism {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'I', 'S', 'M', 'C', 'A', '1'};

// What precedes every payload. The key is stored again so that a file renamed by hand (or a
// hash clash of file names on a case-folding file system) is not taken for another entry.
struct EntryHeader {
    char magic[8];
    uint32_t format;
    uint32_t keyLength;
    uint64_t payloadBytes;
    uint64_t payloadChecksum;
    char key[64];
};
static_assert(sizeof(EntryHeader) == 96);

// Writes all of `bytes` to fd, or returns false.
bool writeAll(int fd, const char *bytes, size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, bytes, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        bytes += n;
        size -= size_t(n);
    }
    return true;
}

} // namespace

DiskCache::DiskCache(DiskCacheOptions options) : options_(std::move(options)) {}

std::filesystem::path DiskCache::defaultDirectory() {
    if (const char *dir = std::getenv("PRISM_CACHE_DIR"); dir && *dir)
        return dir;
    if (const char *xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "prism";
    if (const char *home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "prism";
    return {};
}

std::filesystem::path DiskCache::entryPath(std::string_view kind, std::string_view key) const {
    return options_.directory / (std::string(kind) + "-" + std::string(key) + ".bin");
}

void DiskCache::warn(const std::string &message) const {
    if (options_.warn)
        options_.warn(message);
    else
        std::fprintf(stderr, "prism: warning: cache: %s\n", message.c_str());
}

std::optional<CacheEntry> DiskCache::load(std::string_view kind, std::string_view key,
                                          uint32_t format) const {
    std::filesystem::path path = entryPath(kind, key);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return std::nullopt;
    CacheEntry entry;
    std::string_view bytes;
    const char *problem = nullptr;
    EntryHeader header{};
    try {
        entry.file = std::make_unique<MappedFile>(path, "cache entry");
        bytes = entry.file->bytes();
    } catch (const Error &) {
        problem = "cannot be read";
    }
    if (!problem && bytes.size() < sizeof header)
        problem = "is truncated";
    if (!problem) {
        std::memcpy(&header, bytes.data(), sizeof header);
        if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0)
            problem = "is not a Prism cache entry";
        else if (header.format != format)
            problem = "was written by another version of Prism";
        else if (header.keyLength != key.size() || key.size() > sizeof header.key ||
                 std::string_view(header.key, key.size()) != key)
            problem = "holds another key";
        else if (header.payloadBytes != bytes.size() - sizeof header)
            problem = "is truncated or too long";
        else if (checksum64(bytes.data() + sizeof header, bytes.size() - sizeof header) !=
                 header.payloadChecksum)
            problem = "fails its checksum";
    }
    if (problem) {
        warn("entry '" + path.string() + "' " + problem + "; removed, made anew");
        std::filesystem::remove(path, ec);
        return std::nullopt;
    }
    // Least recently used: a hit makes the entry new again.
    std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), ec);
    entry.payload = bytes.substr(sizeof header);
    return entry;
}

void DiskCache::discard(std::string_view kind, std::string_view key, const std::string &why) const {
    std::filesystem::path path = entryPath(kind, key);
    std::error_code ec;
    std::filesystem::remove(path, ec);
    warn("entry '" + path.string() + "' is damaged (" + why + "); removed, made anew");
}

void DiskCache::store(std::string_view kind, std::string_view key, uint32_t format,
                      std::string_view payload) const {
    store(kind, key, format, std::span<const std::string_view>(&payload, 1));
}

void DiskCache::store(std::string_view kind, std::string_view key, uint32_t format,
                      std::span<const std::string_view> pieces) const {
    if (options_.directory.empty() || key.size() > sizeof(EntryHeader::key))
        return;
    std::error_code ec;
    std::filesystem::create_directories(options_.directory, ec);
    std::filesystem::path path = entryPath(kind, key);
    std::string temporary = path.string() + ".tmp-XXXXXX";
    int fd = ::mkstemp(temporary.data());
    if (fd < 0) {
        if (!saidUnwritable_.exchange(true))
            warn("cannot write in '" + options_.directory.string() + "': " + std::strerror(errno) +
                 "; going on without the cache");
        return;
    }
    EntryHeader header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.format = format;
    header.keyLength = uint32_t(key.size());
    header.payloadBytes = 0;
    for (std::string_view piece : pieces)
        header.payloadBytes += piece.size();
    header.payloadChecksum = checksum64(pieces);
    std::memcpy(header.key, key.data(), key.size());
    bool written = writeAll(fd, reinterpret_cast<const char *>(&header), sizeof header);
    for (std::string_view piece : pieces)
        written = written && writeAll(fd, piece.data(), piece.size());
    written = ::close(fd) == 0 && written;
    if (!written || std::rename(temporary.c_str(), path.c_str()) != 0) {
        warn("cannot write '" + path.string() + "' (disk full?); going on without it");
        std::remove(temporary.c_str());
        return;
    }
    trim(path);
}

void DiskCache::trim(const std::filesystem::path &keep) const {
    struct Entry {
        std::filesystem::path path;
        std::filesystem::file_time_type used;
        uint64_t bytes;
    };
    std::vector<Entry> entries;
    uint64_t total = 0;
    std::error_code ec;
    for (const auto &file : std::filesystem::directory_iterator(options_.directory, ec)) {
        if (file.path().extension() != ".bin" || !file.is_regular_file(ec))
            continue;
        Entry e{file.path(), file.last_write_time(ec), file.file_size(ec)};
        if (ec)
            continue; // removed by another process meanwhile
        total += e.bytes;
        entries.push_back(std::move(e));
    }
    std::sort(entries.begin(), entries.end(),
              [](const Entry &a, const Entry &b) { return a.used < b.used; });
    for (const Entry &e : entries)
        if (e.path == keep && e.bytes > options_.maxBytes) { // alone over the cap: not kept,
            std::filesystem::remove(e.path, ec);             // and no reason to drop the rest
            return;
        }
    for (const Entry &e : entries) {
        if (total <= options_.maxBytes)
            break;
        if (e.path == keep)
            continue; // the entry just written stays
        std::filesystem::remove(e.path, ec);
        total -= e.bytes;
    }
}

} // namespace prism
