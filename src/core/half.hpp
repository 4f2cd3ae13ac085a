#pragma once
// IEEE 754 binary16 ("half") conversions, bit-exact on every CPU: integer
// operations only, rounding to nearest even as the standard says, so a
// frame's half-float colour has the same bits whether F16C exists or not.
// Frames keep their colour as half floats: what EXR stores, a 64 Ki-entry
// table away from 8-bit sRGB for PNG, and half the memory traffic of float.
#include <cstdint>
#include <cstring>

#include <glm/vec4.hpp>

#include "core/image.hpp"
#include "core/simd_math.hpp"

namespace facet {

struct Rgba16F {
    uint16_t r, g, b, a;
};

using HalfColorImage = Image<Rgba16F>;  // linear RGBA, half floats

// Eight floats to halves (in the low 16 bits of each lane): overflow goes to
// infinity, tiny values to subnormals or zero, NaN to a quiet NaN with the
// top of its payload, exactly as the F16C instruction does, so that either
// gives the same bits (float_to_half uses F16C where the build has it).
[[gnu::always_inline]] inline simd::vi float_to_half_portable(simd::vf value) {
    using simd::splat_i;
    using simd::vi;
    vi bits;
    std::memcpy(&bits, &value, sizeof bits);
    const vi sign = (bits >> 16) & splat_i(0x8000);
    const vi magnitude = bits & splat_i(0x7fffffff);
    // Normal halves: rebias the exponent, round the 13 dropped bits to even.
    const vi rebiased = magnitude - splat_i((127 - 15) << 23);
    const vi odd = (rebiased >> 13) & splat_i(1);
    const vi normal = (rebiased + splat_i(0x0fff) + odd) >> 13;
    // Subnormal halves (|x| < 2^-14): add 0.5 so the float adder aligns the
    // mantissa and rounds to even, then take the low bits.
    simd::vf tiny;
    std::memcpy(&tiny, &magnitude, sizeof tiny);
    tiny = tiny + simd::splat(0.5f);
    vi tiny_bits;
    std::memcpy(&tiny_bits, &tiny, sizeof tiny_bits);
    const vi subnormal = tiny_bits - splat_i(0x3f000000);
    vi out = magnitude < splat_i(113 << 23) ? subnormal : normal;
    out = magnitude >= splat_i(143 << 23) ? splat_i(0x7c00) : out;  // >= 65520: infinity
    const vi nan = splat_i(0x7e00) | ((magnitude >> 13) & splat_i(0x3ff));
    out = magnitude > splat_i(0x7f800000) ? nan : out;
    return out | sign;
}

// Floats as facet stores them in halves: beyond the largest finite half,
// 65504, infinity included, they are 65504 (and below -65504, -65504);
// NaN stays NaN. A colour past the range would otherwise be infinity,
// which no tone curve can map to its white, and an EXR reader shows as a
// hole (docs/passes.md).
[[gnu::always_inline]] inline simd::vf saturate_to_half_range(simd::vf value) {
    const simd::vf largest = simd::splat(65504.0f);
    value = value > largest ? largest : value;  // a NaN compares false and stays
    return value < -largest ? -largest : value;
}

// Eight floats to halves as facet stores them: saturated to the half range
// (saturate_to_half_range), then rounded to nearest even.
[[gnu::always_inline]] inline simd::vh float_to_half_bits(simd::vf value) {
    value = saturate_to_half_range(value);
#if FACET_SIMD_F16C
    return simd::half_bits_f16c(value);
#else
    return __builtin_convertvector(float_to_half_portable(value), simd::vh);
#endif
}

[[gnu::always_inline]] inline simd::vi float_to_half(simd::vf value) {
    return __builtin_convertvector(float_to_half_bits(value), simd::vi);
}

// RGBA planes of eight pixels into eight half-float RGBA pixels in memory,
// streamed (simd::store_streaming).
[[gnu::always_inline]] inline void store_half_rgba(const simd::vf (&planes)[4], Rgba16F* pixels) {
    static_assert(sizeof(Rgba16F) == 4 * sizeof(uint16_t));
    const simd::vh halves[4] = {float_to_half_bits(planes[0]), float_to_half_bits(planes[1]),
                                float_to_half_bits(planes[2]), float_to_half_bits(planes[3])};
    simd::store_interleaved4(halves, reinterpret_cast<uint16_t*>(pixels));
}

inline uint16_t float_to_half(float value) {
    return static_cast<uint16_t>(float_to_half(simd::splat(value))[0]);
}

inline float half_to_float(uint16_t h) {
    const uint32_t sign = static_cast<uint32_t>(h & 0x8000) << 16;
    const uint32_t exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    uint32_t bits;
    if (exponent == 0x1f) {
        bits = sign | 0x7f800000u | (mantissa << 13);  // infinity, NaN
    } else if (exponent != 0) {
        bits = sign | ((exponent + 112) << 23) | (mantissa << 13);
    } else if (mantissa == 0) {
        bits = sign;
    } else {  // subnormal: exact as a float
        float f = static_cast<float>(mantissa) * (1.0f / 16777216.0f);  // 2^-24
        std::memcpy(&bits, &f, sizeof bits);
        bits |= sign;
    }
    float out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
}

// The four channels through one eight-lane conversion (the same bits as
// four single ones: each lane is converted alone).
inline Rgba16F to_half(const glm::vec4& c) {
    const simd::vi h = float_to_half(simd::vf{c.r, c.g, c.b, c.a, 0.0f, 0.0f, 0.0f, 0.0f});
    return {static_cast<uint16_t>(h[0]), static_cast<uint16_t>(h[1]), static_cast<uint16_t>(h[2]),
            static_cast<uint16_t>(h[3])};
}

inline glm::vec4 to_float(const Rgba16F& c) {
    return {half_to_float(c.r), half_to_float(c.g), half_to_float(c.b), half_to_float(c.a)};
}

// Whole images, for tests, contact sheets and anything else that wants floats.
ColorImage to_float_image(const HalfColorImage& image);
HalfColorImage to_half_image(const ColorImage& image);

}  // namespace facet
