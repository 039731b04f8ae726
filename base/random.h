// Deterministic random numbers (docs/design.md: Determinism): PCG32 (O'Neill 2014)
// with selectable streams, as in pbrt's RNG::SetSequence. Every derived item
// (a node, a lot, a texel) gets its own stream from a hash of its identity, so
// no value depends on the order in which items are produced.
#pragma once
#include <cstdint>

namespace boxlod {

// SplitMix64 finaliser: spreads a 64-bit value over all bits.
inline std::uint64_t mix_bits(std::uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ULL;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebULL;
    v ^= v >> 31;
    return v;
}

// An identity for a child item: the parent's identity and the child's ordinal.
inline std::uint64_t hash_combine(std::uint64_t parent, std::uint64_t ordinal) {
    return mix_bits(parent ^ mix_bits(ordinal + 0x9e3779b97f4a7c15ULL));
}

class Pcg32 {
public:
    Pcg32(std::uint64_t seed, std::uint64_t stream) {
        increment_ = (stream << 1u) | 1u;
        next_uint();
        state_ += seed;
        next_uint();
    }

    std::uint32_t next_uint() {
        std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + increment_;
        auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        auto rotation = std::uint32_t(old >> 59u);
        return (xorshifted >> rotation) | (xorshifted << ((~rotation + 1u) & 31u));
    }

    // Uniform in [0, 1); 32 random bits, exact in a double.
    double uniform() { return next_uint() * 0x1p-32; }

    double uniform(double low, double high) { return low + (high - low) * uniform(); }

private:
    std::uint64_t state_ = 0;
    std::uint64_t increment_ = 1;
};

}  // namespace boxlod
