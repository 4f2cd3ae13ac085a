#pragma once
// Small scalar helpers shared by the stylised shading models. Everything
// here is IEEE-exact arithmetic (add, mul, div, sqrt, compares), so a
// result has the same bits on every x86-64, like core/simd_math.hpp.
#include <algorithm>

#include "core/simd_math.hpp"

namespace facet {

inline float saturate(float x) {
    return std::clamp(x, 0.0f, 1.0f);
}

// x^s for x in [0, 1] and s >= 0 with the same polynomial log2/exp2 as the
// eight-lane lighting (simd::vpow_unit), so a future batch version of a
// style gives the same bits as this scalar one. x <= 0 gives 0.
inline float pow_unit(float x, float s) {
    if (!(x > 0.0f)) return 0.0f;
    return simd::vpow_unit(simd::splat(std::min(x, 1.0f)), simd::splat(s))[0];
}

// Hermite smoothstep from 0 at `lo` to 1 at `hi` (lo < hi).
inline float smoothstep(float lo, float hi, float x) {
    const float t = saturate((x - lo) / (hi - lo));
    return t * t * (3.0f - 2.0f * t);
}

// A band edge at `threshold`: a hard step (x >= threshold) when width <= 0,
// otherwise a smoothstep over [threshold - width/2, threshold + width/2].
// The softened edge is what keeps toon bands from aliasing into stairs.
inline float band_edge(float x, float threshold, float width) {
    if (width <= 0.0f) return x >= threshold ? 1.0f : 0.0f;
    return smoothstep(threshold - 0.5f * width, threshold + 0.5f * width, x);
}

}  // namespace facet
