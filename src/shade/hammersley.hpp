#pragma once
// Hammersley's point set (Hammersley 1960), the deterministic samples that
// the BRDF's DFG table and the environment's prefiltering integrate with:
// point i of n is (i / n, radical_inverse_base2(i)). Fixed points rather
// than random ones, so the tables have the same bits on every run.
#include <cstdint>

namespace facet::pbr {

// The radical inverse of i in base 2 (van der Corput), the second
// coordinate of Hammersley's point set: i's bits mirrored about the binary
// point. Exact: a 32-bit integer times 2^-32.
inline double radical_inverse_base2(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
    i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
    i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
    i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
    return static_cast<double>(i) * 0x1p-32;
}

}  // namespace facet::pbr
