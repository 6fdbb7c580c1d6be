#include "cache/content_hash.h"

#include <cstdio>

// The state's layout, for a digest state on the stack (checksum64 of pieces).
#define XXH_STATIC_LINKING_ONLY
#include <xxhash.h>

#include "core/error.h"

namespace prism {

struct ContentHash::State {
    XXH3_state_t *xxh = nullptr;
};

ContentHash::ContentHash() : state_(std::make_unique<State>()) {
    state_->xxh = XXH3_createState();
    if (!state_->xxh || XXH3_128bits_reset(state_->xxh) != XXH_OK)
        throw Error("cannot start an XXH3 digest (out of memory)");
}

ContentHash::~ContentHash() {
    XXH3_freeState(state_->xxh);
}

ContentHash &ContentHash::bytes(const void *data, size_t size) {
    if (size > 0)
        XXH3_128bits_update(state_->xxh, data, size);
    return *this;
}

std::string ContentHash::hex() const {
    XXH128_hash_t digest = XXH3_128bits_digest(state_->xxh);
    char text[33];
    std::snprintf(text, sizeof text, "%016llx%016llx",
                  static_cast<unsigned long long>(digest.high64),
                  static_cast<unsigned long long>(digest.low64));
    return text;
}

uint64_t checksum64(const void *data, size_t size) {
    return XXH3_64bits(data, size);
}

uint64_t checksum64(std::span<const std::string_view> pieces) {
    if (pieces.size() == 1)
        return checksum64(pieces[0].data(), pieces[0].size());
    // XXH3's streaming digest is its one-shot digest of everything given (xxhash.h); the state
    // on the stack, so that DiskCache::store, which never throws, allocates nothing for it.
    XXH3_state_t state;
    XXH3_INITSTATE(&state);
    XXH3_64bits_reset(&state);
    for (std::string_view piece : pieces)
        XXH3_64bits_update(&state, piece.data(), piece.size());
    return XXH3_64bits_digest(&state);
}

} // namespace prism
