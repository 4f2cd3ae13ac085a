#pragma once
// Integer hashing for procedural textures: the same bits on every platform
// and compiler, no global random state, any value reachable directly from
// (seed, stream, index) without generating the ones before it.
#include <cstdint>

namespace facet {

// Chris Wellons' "lowbias32" integer hash (hash-prospector, 2020): a
// well-mixed bijection on 32-bit integers.
constexpr uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

constexpr uint32_t hash32(uint32_t a, uint32_t b) {
    return hash32(a ^ hash32(b + 0x9e3779b9U));
}

constexpr uint32_t hash32(uint32_t a, uint32_t b, uint32_t c) {
    return hash32(hash32(a, b), c);
}

constexpr uint32_t hash32(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    return hash32(hash32(a, b, c), d);
}

// The top 24 bits as a float in [0, 1): exact, no rounding.
constexpr float hash_unit(uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

}  // namespace facet
