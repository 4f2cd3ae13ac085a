#pragma once
// Shading arithmetic written once, for one point (float) and for eight
// (simd::vf): the BRDF, the lights and normalising are templates on the
// number type T, so a point's float result is lane 0 of the eight-lane one,
// to the bit (tests/test_pbr_lanes.cpp). Only IEEE-exact operations (add,
// mul, div, sqrt, compares, selects), as core/simd_math.hpp.
#include <array>
#include <cmath>
#include <type_traits>

#include "core/simd_math.hpp"

namespace facet::lanes {

// The compare result of T: bool for one point, an integer vector for eight.
template <typename T>
struct Traits;
template <>
struct Traits<float> {
    using Mask = bool;
};
template <>
struct Traits<simd::vf> {
    using Mask = simd::vi;
};
template <typename T>
using Mask = typename Traits<T>::Mask;

template <typename T>
[[gnu::always_inline]] inline T splat(float x) {
    if constexpr (std::is_same_v<T, float>)
        return x;
    else
        return simd::splat(x);
}

[[gnu::always_inline]] inline float square_root(float x) {
    return std::sqrt(x);
}
[[gnu::always_inline]] inline simd::vf square_root(simd::vf x) {
    return simd::vsqrt(x);
}

// x^s for x in (0, 1] and s >= 0, and 2^y for y in [-126, 127]: the
// polynomials of core/simd_math.hpp (vpow_unit, vexp2). One point is lane 0
// of eight, so both forms give the same bits.
[[gnu::always_inline]] inline simd::vf power_unit(simd::vf x, simd::vf s) {
    return simd::vpow_unit(x, s);
}
[[gnu::always_inline]] inline float power_unit(float x, float s) {
    return simd::vpow_unit(simd::splat(x), simd::splat(s))[0];
}
[[gnu::always_inline]] inline simd::vf exp2(simd::vf y) {
    return simd::vexp2(y);
}
[[gnu::always_inline]] inline float exp2(float y) {
    return simd::vexp2(simd::splat(y))[0];
}

// cos(x), simd::vcos's polynomial (lane 0 of it for one point).
[[gnu::always_inline]] inline simd::vf cosine(simd::vf x) {
    return simd::vcos(x);
}
[[gnu::always_inline]] inline float cosine(float x) {
    return simd::vcos(simd::splat(x))[0];
}

// A mask with every lane set to `value`.
template <typename T>
[[gnu::always_inline]] inline Mask<T> splat_mask(bool value) {
    if constexpr (std::is_same_v<T, float>)
        return value;
    else
        return simd::splat_i(value ? -1 : 0);
}

// `mask ? a : b`, lane by lane.
[[gnu::always_inline]] inline float select(bool mask, float a, float b) {
    return mask ? a : b;
}
[[gnu::always_inline]] inline simd::vf select(simd::vi mask, simd::vf a, simd::vf b) {
    return mask ? a : b;
}

// Whether any lane is set: a one-point mask is itself.
[[gnu::always_inline]] inline bool any(bool mask) {
    return mask;
}
[[gnu::always_inline]] inline bool any(simd::vi mask) {
    return simd::movemask(mask) != 0;
}

// a < b ? a : b, and a > b ? a : b, as simd::vmin and vmax (a NaN in `a`
// gives `b`).
[[gnu::always_inline]] inline float min_of(float a, float b) {
    return a < b ? a : b;
}
[[gnu::always_inline]] inline simd::vf min_of(simd::vf a, simd::vf b) {
    return simd::vmin(a, b);
}
[[gnu::always_inline]] inline float max_of(float a, float b) {
    return a > b ? a : b;
}
[[gnu::always_inline]] inline simd::vf max_of(simd::vf a, simd::vf b) {
    return simd::vmax(a, b);
}

// x clamped to [0, 1] in std::clamp's order (a NaN stays).
template <typename T>
[[gnu::always_inline]] inline T clamp01(T x) {
    return select(x < splat<T>(0.0f), splat<T>(0.0f),
                  select(splat<T>(1.0f) < x, splat<T>(1.0f), x));
}

template <typename T>
using Vec3 = std::array<T, 3>;

template <typename T>
[[gnu::always_inline]] inline T dot(const Vec3<T>& a, const Vec3<T>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// `v` over its length, or `fallback` where its length is 0.
template <typename T>
[[gnu::always_inline]] inline Vec3<T> normalise_or(const Vec3<T>& v, const Vec3<T>& fallback) {
    const T length = square_root(dot(v, v));
    const Mask<T> ok = length > splat<T>(0.0f);
    const T inverse = 1.0f / select(ok, length, splat<T>(1.0f));
    return {select(ok, v[0] * inverse, fallback[0]), select(ok, v[1] * inverse, fallback[1]),
            select(ok, v[2] * inverse, fallback[2])};
}

// a x b.
template <typename T>
[[gnu::always_inline]] inline Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// 2 (n.v) n - v: v mirrored about n.
template <typename T>
[[gnu::always_inline]] inline Vec3<T> reflect(const Vec3<T>& n, const Vec3<T>& v) {
    const T twice = 2.0f * dot(n, v);
    return {twice * n[0] - v[0], twice * n[1] - v[1], twice * n[2] - v[2]};
}

}  // namespace facet::lanes
