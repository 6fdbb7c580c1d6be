#pragma once
// A flat binary record of values and arrays, for cache entries: written in one pass, read back
// with every length checked against what is left, so that a damaged entry throws
// BlobFormatError instead of reading past its end. Host byte order: an entry is only ever read
// by the machine (and program version) that wrote it, which the cache's key ensures.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/error.h"
#include "core/huge_pages.h"

namespace prism {

class BlobFormatError : public Error {
public:
    using Error::Error;
};

// Writes a record as a list of pieces: runs of small values, copied here, and large arrays
// where their owners hold them, not copied (a 1M-triangle grid's entry is 90 MB: packed into
// one string first, it was that much fresh memory and a copy more, 44-420 ms of a cold render;
// DiskCache::store writes the pieces one after the other). The pieces' bytes in order are the
// record, the same as take()'s one string.
class BlobWriter {
public:
    // Arrays from this many bytes are borrowed, not copied.
    static constexpr size_t kBorrowFrom = 4096;

    template <typename T> void value(const T &v) {
        static_assert(std::is_trivially_copyable_v<T>);
        copy(&v, sizeof v);
    }
    // Borrows the array's bytes where it is large: `v` must stay as it is while the pieces are
    // used.
    template <typename T> void values(const std::vector<T> &v) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(uint64_t(v.size()));
        size_t bytes = v.size() * sizeof(T);
        if (bytes >= kBorrowFrom)
            order_.push_back({std::string_view(reinterpret_cast<const char *>(v.data()), bytes)});
        else
            copy(v.data(), bytes);
    }
    void text(std::string_view s) {
        value(uint64_t(s.size()));
        copy(s.data(), s.size());
    }

    // The record's bytes, piece by piece, in order.
    std::vector<std::string_view> pieces() const {
        std::vector<std::string_view> out;
        for (const Piece &p : order_)
            out.push_back(p.run == kBorrowed ? p.borrowed : std::string_view(runs_[p.run]));
        return out;
    }
    // The record in one string (a copy of every borrowed array).
    std::string take() const {
        std::vector<std::string_view> all = pieces();
        size_t size = 0;
        for (std::string_view piece : all)
            size += piece.size();
        std::string bytes;
        bytes.reserve(size);
        for (std::string_view piece : all)
            bytes.append(piece);
        return bytes;
    }

private:
    static constexpr size_t kBorrowed = SIZE_MAX;
    struct Piece {
        std::string_view borrowed;
        size_t run = kBorrowed; // else runs_[run], viewed when the pieces are asked for
    };

    void copy(const void *data, size_t size) {
        if (size == 0)
            return;
        if (order_.empty() || order_.back().run == kBorrowed) {
            runs_.emplace_back();
            order_.push_back({{}, runs_.size() - 1});
        }
        runs_.back().append(static_cast<const char *>(data), size);
    }

    std::vector<Piece> order_;
    std::deque<std::string> runs_; // a deque: a run's string stays where it is as runs are added
};

class BlobReader {
public:
    explicit BlobReader(std::string_view bytes) : rest_(bytes) {}

    template <typename T> T value() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        std::memcpy(&v, take(sizeof v), sizeof v);
        return v;
    }
    template <typename T> std::vector<T> values() {
        static_assert(std::is_trivially_copyable_v<T>);
        uint64_t count = value<uint64_t>();
        if (count > rest_.size() / sizeof(T))
            throw BlobFormatError("an array runs past the end of the entry");
        std::vector<T> v;
        reserveInHugePages(v, size_t(count));
        const char *from = take(size_t(count) * sizeof(T));
        if (reinterpret_cast<uintptr_t>(from) % alignof(T) == 0) { // one pass: no zeros first
            const T *first = reinterpret_cast<const T *>(from);
            v.assign(first, first + count);
            return v;
        }
        v.resize(size_t(count));
        if (count > 0) // an empty vector's data() may be null, which memcpy must not be given
            std::memcpy(v.data(), from, size_t(count) * sizeof(T));
        return v;
    }
    // An array where its bytes lie, not copied, where they lie aligned for T (an entry's
    // mapped bytes start on a page and its arrays of 4-byte elements keep 4-byte alignment);
    // else copied into `copy`. The span lives as long as the bytes read from (or `copy`).
    template <typename T> std::span<const T> view(std::vector<T> &copy) {
        static_assert(std::is_trivially_copyable_v<T>);
        uint64_t count = value<uint64_t>();
        if (count > rest_.size() / sizeof(T))
            throw BlobFormatError("an array runs past the end of the entry");
        const char *from = take(size_t(count) * sizeof(T));
        if (reinterpret_cast<uintptr_t>(from) % alignof(T) == 0)
            return {reinterpret_cast<const T *>(from), size_t(count)};
        copy.resize(size_t(count));
        if (count > 0)
            std::memcpy(copy.data(), from, size_t(count) * sizeof(T));
        return copy;
    }
    std::string text() {
        uint64_t size = value<uint64_t>();
        if (size > rest_.size())
            throw BlobFormatError("a string runs past the end of the entry");
        return std::string(take(size_t(size)), size_t(size));
    }
    bool atEnd() const { return rest_.empty(); }

private:
    const char *take(size_t n) {
        if (n > rest_.size())
            throw BlobFormatError("the entry ends early");
        const char *at = rest_.data();
        rest_.remove_prefix(n);
        return at;
    }
    std::string_view rest_;
};

} // namespace prism
