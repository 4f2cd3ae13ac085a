#pragma once
// The sRGB transfer function (IEC 61966-2-1), in one place for every module
// that decodes or encodes sRGB values.
namespace facet {

// sRGB-encoded value in [0, 1] -> linear light.
float srgb_to_linear(float c);

// Linear light in [0, 1] (clamped) -> sRGB-encoded value. Double precision,
// for building the encoder's lookup table.
double linear_to_srgb(double c);

// Relative luminance of linear RGB, Rec. 709 weights; for floats or SIMD
// lanes alike.
template <typename T>
T rec709_luminance(const T& r, const T& g, const T& b) {
    return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

}  // namespace facet
