#pragma once
// Digests of content, for the on-disk cache's keys and checksums (XXH3 from Debian's
// libxxhash: 128 bits for keys, where a collision would hand back someone else's grid, 64
// for checksums of what was read back). Not cryptographic: the cache lives in the user's own
// directory, so it guards against accidents (a truncated or corrupted file), not attacks.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace prism {

class ContentHash {
public:
    ContentHash();
    ~ContentHash();
    ContentHash(const ContentHash &) = delete;
    ContentHash &operator=(const ContentHash &) = delete;

    ContentHash &bytes(const void *data, size_t size);
    // A value's bytes: only for types without padding (whose bytes are all value), such as
    // integers, floats and GLM vectors of them.
    template <typename T> ContentHash &value(const T &v) {
        static_assert(std::is_trivially_copyable_v<T>);
        return bytes(&v, sizeof v);
    }
    // Length first, so that ("ab", "c") and ("a", "bc") differ.
    ContentHash &text(std::string_view s) {
        value(uint64_t(s.size()));
        return bytes(s.data(), s.size());
    }
    template <typename T> ContentHash &values(const std::vector<T> &v) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(uint64_t(v.size()));
        return bytes(v.data(), v.size() * sizeof(T));
    }
    // The 128-bit digest of everything added so far, as 32 lowercase hex digits.
    std::string hex() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// XXH3's 64-bit digest of `size` bytes.
uint64_t checksum64(const void *data, size_t size);
// The same digest of the pieces' bytes one after the other, as if they were one array.
uint64_t checksum64(std::span<const std::string_view> pieces);

} // namespace prism
