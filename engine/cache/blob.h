#pragma once
// A flat binary record of values and arrays, for cache entries: written in one pass, read back
// with every length checked against what is left, so that a damaged entry throws
// BlobFormatError instead of reading past its end. Host byte order: an entry is only ever read
// by the machine (and program version) that wrote it, which the cache's key ensures.
#include <cstddef>
#include <cstdint>
#include <cstring>
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

class BlobWriter {
public:
    template <typename T> void value(const T &v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char *>(&v), sizeof v);
    }
    template <typename T> void values(const std::vector<T> &v) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(uint64_t(v.size()));
        bytes_.append(reinterpret_cast<const char *>(v.data()), v.size() * sizeof(T));
    }
    void text(std::string_view s) {
        value(uint64_t(s.size()));
        bytes_.append(s);
    }
    void reserve(size_t bytes) { bytes_.reserve(bytes); }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
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
        v.resize(size_t(count));
        const char *from = take(size_t(count) * sizeof(T));
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
