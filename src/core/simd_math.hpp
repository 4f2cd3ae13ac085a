#pragma once
// Eight-lane float maths with GCC vector extensions. Only IEEE-exact
// operations are used (add, mul, div, sqrt, compares, bit moves), so every
// lane gives the same bits as the same code run one value at a time, on
// any CPU: a build for AVX2 (FACET_SIMD, CMakeLists.txt), one for baseline
// SSE2 and a generic one give the same images. No FMA: contraction is off.
//
// Every processor intrinsic in facet is in this file, each next to the
// plain vector code it speeds up, so a port to another architecture
// (aarch64) changes this file alone. FACET_SIMD=generic defines
// FACET_SIMD_GENERIC, which leaves every intrinsic out.
#include <cstdint>
#include <cstring>

#if !defined(FACET_SIMD_GENERIC) && defined(__AVX__)
#define FACET_SIMD_AVX 1
#endif
#if !defined(FACET_SIMD_GENERIC) && defined(__F16C__)
#define FACET_SIMD_F16C 1
#endif
#if !defined(FACET_SIMD_GENERIC) && defined(__SSE2__)
#define FACET_SIMD_SSE2 1
#include <immintrin.h>
#endif

// The vectors are 32 bytes; on baseline x86-64 GCC warns that passing them
// by value differs from AVX code. The whole program is built for one ISA,
// so no call crosses that boundary.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace facet::simd {

constexpr int kLanes = 8;
typedef float vf __attribute__((vector_size(32)));
typedef int32_t vi __attribute__((vector_size(32)));
typedef uint16_t vh __attribute__((vector_size(16)));  // eight halves' bits

// With AVX the intrinsics: GCC 12 builds a braced {v, v, ...} or a loop
// of lane stores with eight inserts (or through the stack), not one broadcast.
[[gnu::always_inline]] inline vf splat(float v) {
#if FACET_SIMD_AVX
    return (vf)_mm256_set1_ps(v);
#else
    return vf{v, v, v, v, v, v, v, v};
#endif
}
[[gnu::always_inline]] inline vi splat_i(int32_t v) {
#if FACET_SIMD_AVX
    return (vi)_mm256_set1_epi32(v);
#else
    return vi{v, v, v, v, v, v, v, v};
#endif
}

// Bit i set where lane i of the mask is set (all ones).
[[gnu::always_inline]] inline unsigned movemask(vi mask) {
#if FACET_SIMD_AVX
    return static_cast<unsigned>(_mm256_movemask_ps((__m256)mask));
#else
    unsigned bits = 0;
    for (int i = 0; i < kLanes; ++i) bits |= (mask[i] != 0 ? 1u : 0u) << i;
    return bits;
#endif
}

[[gnu::always_inline]] inline vf vsqrt(vf x) {
    vf r;
    for (int i = 0; i < kLanes; ++i) r[i] = __builtin_sqrtf(x[i]);
    return r;
}

[[gnu::always_inline]] inline vf vmax(vf a, vf b) {
    return a > b ? a : b;
}
[[gnu::always_inline]] inline vf vmin(vf a, vf b) {
    return a < b ? a : b;
}

// Eight float lanes to memory. Where the address allows, a streaming store
// that skips the cache: frame buffers are written once and read by the
// next stage long after. Call streaming_stores_done() before the buffer is
// handed on.
[[gnu::always_inline]] inline void store_streaming(float* out, vf value) {
#if FACET_SIMD_AVX
    if ((reinterpret_cast<uintptr_t>(out) & 31) == 0) return _mm256_stream_ps(out, (__m256)value);
#endif
    std::memcpy(out, &value, sizeof value);
}

// Four planes of eight 16-bit values to eight interleaved records of four
// (RGBA planes to RGBA pixels), streamed like store_streaming where the
// address allows.
[[gnu::always_inline]] inline void store_interleaved4(const vh (&planes)[4], uint16_t* out) {
#if FACET_SIMD_SSE2
    const __m128i rg_lo = _mm_unpacklo_epi16((__m128i)planes[0], (__m128i)planes[1]);
    const __m128i rg_hi = _mm_unpackhi_epi16((__m128i)planes[0], (__m128i)planes[1]);
    const __m128i ba_lo = _mm_unpacklo_epi16((__m128i)planes[2], (__m128i)planes[3]);
    const __m128i ba_hi = _mm_unpackhi_epi16((__m128i)planes[2], (__m128i)planes[3]);
    const __m128i records[4] = {_mm_unpacklo_epi32(rg_lo, ba_lo), _mm_unpackhi_epi32(rg_lo, ba_lo),
                                _mm_unpacklo_epi32(rg_hi, ba_hi), _mm_unpackhi_epi32(rg_hi, ba_hi)};
    __m128i* to = reinterpret_cast<__m128i*>(out);
    if ((reinterpret_cast<uintptr_t>(out) & 63) == 0) {
        for (int i = 0; i < 4; ++i) _mm_stream_si128(to + i, records[i]);
        return;
    }
    for (int i = 0; i < 4; ++i) _mm_storeu_si128(to + i, records[i]);
#else
    for (int i = 0; i < kLanes; ++i)
        for (int p = 0; p < 4; ++p) out[4 * i + p] = planes[p][i];
#endif
}

// Bit i set where byte i of the 16 bytes at `a` equals byte i of the 16 at
// `b` (unaligned): the deflate coder's search for repeated bytes.
[[gnu::always_inline]] inline unsigned equal_bytes16(const uint8_t* a, const uint8_t* b) {
#if FACET_SIMD_SSE2
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a));
    const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b));
    return static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(x, y)));
#else
    unsigned mask = 0;
    for (int i = 0; i < 16; ++i) mask |= (a[i] == b[i] ? 1u : 0u) << i;
    return mask;
#endif
}

// Orders the streaming stores before whatever follows (another thread
// reading the buffer); without them there is nothing to order.
[[gnu::always_inline]] inline void streaming_stores_done() {
#if FACET_SIMD_SSE2
    _mm_sfence();
#endif
}

#if FACET_SIMD_F16C
// Floats to halves in one instruction, rounding to nearest even: the same
// bits as float_to_half_portable (core/half.hpp), which tests check.
[[gnu::always_inline]] inline vh half_bits_f16c(vf value) {
    return (vh)_mm256_cvtps_ph((__m256)value, _MM_FROUND_TO_NEAREST_INT);
}
#endif

// log2 for positive, normal x. The mantissa is centred on 1 (in
// [sqrt(1/2), sqrt(2))) and log(m) summed as 2 atanh((m-1)/(m+1)), whose
// odd series converges fast there: five terms give about 1e-7 relative.
[[gnu::always_inline]] inline vf vlog2(vf x) {
    vi bits = (vi)x;
    vi exponent = ((bits >> 23) & 0xff) - 127;
    vi mantissa_bits = (bits & 0x7fffff) | 0x3f800000;
    vf m = (vf)mantissa_bits;
    vi big = m > splat(1.41421356f);  // -1 where true
    m = big ? m * 0.5f : m;
    exponent -= big;
    // ln m = 2 atanh t, t = (m - 1) / (m + 1): 2 (t + t^3/3 + ... + t^9/9).
    // The polynomial in u = t^2 by Estrin's scheme (Knuth, TAOCP vol. 2,
    // 4.6.4): pairs of terms at once, so the chain of dependent multiplies
    // and adds is three pairs deep instead of Horner's five. Lighting
    // waits on it.
    vf t = (m - 1.0f) / (m + 1.0f);
    vf u = t * t;
    vf u2 = u * u;
    vf low = 2.0f + u * (2.0f / 3);
    vf high = 2.0f / 5 + u * (2.0f / 7) + u2 * (2.0f / 9);
    vf series = t * (low + u2 * high);
    return __builtin_convertvector(exponent, vf) + series * 1.44269504f;  // 1/ln 2
}

// floor(x) as integers, for |x| < 2^31.
[[gnu::always_inline]] inline vi floor_to_int(vf x) {
    const vi whole = __builtin_convertvector(x, vi);          // truncates towards zero
    return whole + (__builtin_convertvector(whole, vf) > x);  // -1 where it rounded up
}

// 2^y for y in [-126, 127]; smaller y gives about 1e-38. The lighting's
// powers need y <= 0, the sheen's masking (shade/brdf_terms.hpp) up to about 30.
[[gnu::always_inline]] inline vf vexp2(vf y) {
    y = vmax(y, splat(-126.0f));
    const vi whole = floor_to_int(y);
    vf f = y - __builtin_convertvector(whole, vf);  // in [0, 1)
    // e^(f ln 2) by Taylor series to degree 8: error below 1e-7 on [0, 1).
    // Evaluated by Estrin's scheme (as vlog2): terms in pairs, the pairs
    // joined by z^2 and z^4, five multiply-and-add steps deep instead of
    // Horner's eight.
    vf z = f * 0.69314718f;
    vf z2 = z * z;
    vf z4 = z2 * z2;
    vf terms01 = 1.0f + z;
    vf terms23 = 0.5f + z * (1.0f / 6);
    vf terms45 = 1.0f / 24 + z * (1.0f / 120);
    vf terms67 = 1.0f / 720 + z * (1.0f / 5040);
    vf terms03 = terms01 + z2 * terms23;
    vf terms47 = terms45 + z2 * terms67;
    vf p = terms03 + z4 * (terms47 + z4 * (1.0f / 40320));
    vi scale_bits = (whole + 127) << 23;
    return p * (vf)scale_bits;
}

// cos(x) for |x| up to about 1e4 (the thin film's phases, shade/thin_film.hpp):
// x moved by whole turns to [-pi, pi], then the Taylor series of cos to
// x^20/20!, whose truncation error at pi is below 4e-9. The reduction
// costs about |x| * 6e-8 of absolute error.
[[gnu::always_inline]] inline vf vcos(vf x) {
    const vf turns = x * 0.159154943f;  // 1 / (2 pi)
    const vf whole = __builtin_convertvector(floor_to_int(turns + 0.5f), vf);
    const vf r = (turns - whole) * 6.28318531f;
    const vf r2 = r * r;
    vf sum = splat(1.0f);
    for (int k = 10; k >= 1; --k)  // Horner, from x^20/20! down
        sum = 1.0f - r2 * (1.0f / static_cast<float>((2 * k - 1) * (2 * k))) * sum;
    return sum;
}

// x^s for x in (0, 1] and s >= 0, as a highlight needs.
[[gnu::always_inline]] inline vf vpow_unit(vf x, vf s) {
    x = vmax(x, splat(1e-30f));
    return vexp2(s * vlog2(x));
}

}  // namespace facet::simd
