#pragma once
// The generator's own random numbers: PCG32 (O'Neill 2014, XSH-RR output) seeded through
// splitmix64. Only integer arithmetic, so a seed gives the same stream with every compiler and
// standard library (std::uniform_*_distribution does not promise that).
#include <cstdint>
#include <stdexcept>

namespace prism::scenegen {

// Steele, Lea & Flood 2014: one 64-bit mixing step, used here to spread a small seed.
inline uint64_t splitmix64(uint64_t &state) {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

class Pcg32 {
public:
    explicit Pcg32(uint64_t seed) {
        uint64_t mix = seed;
        uint64_t initState = splitmix64(mix);
        uint64_t stream = splitmix64(mix);
        increment_ = (stream << 1u) | 1u;
        state_ = 0;
        next();
        state_ += initState;
        next();
    }

    uint32_t next() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ull + increment_;
        auto xorShifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        auto rot = uint32_t(old >> 59u);
        return (xorShifted >> rot) | (xorShifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, n), without modulo bias (rejects the short top range).
    uint32_t below(uint32_t n) {
        if (n == 0)
            throw std::invalid_argument("Pcg32::below(0)");
        uint32_t threshold = (0u - n) % n;
        for (;;) {
            uint32_t r = next();
            if (r >= threshold)
                return r % n;
        }
    }

    // Uniform integer in [lo, hi], both included.
    int64_t between(int64_t lo, int64_t hi) {
        if (hi < lo || hi - lo >= int64_t(UINT32_MAX))
            throw std::invalid_argument("Pcg32::between: empty or too wide range");
        return lo + int64_t(below(uint32_t(hi - lo + 1)));
    }

private:
    uint64_t state_ = 0;
    uint64_t increment_ = 1;
};

} // namespace prism::scenegen
