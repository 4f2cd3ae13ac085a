#pragma once
// The sRGB transfer function (IEC 61966-2-1), in one place for every module
// that decodes or encodes sRGB values.
namespace facet {

// sRGB-encoded value in [0, 1] -> linear light.
float srgb_to_linear(float c);

// Linear light in [0, 1] (clamped) -> sRGB-encoded value. Double precision,
// for building the encoder's lookup table.
double linear_to_srgb(double c);

// CIE 1976 lightness L* / 100 of relative luminance y in [0, 1]: 1.16
// y^(1/3) - 0.16, and 9.033 y below (6/29)^3 (CIE 15:2004).
float cie_lightness(float y);

// Relative luminance of linear RGB, Rec. 709 weights; for floats or SIMD
// lanes alike.
template <typename T>
T rec709_luminance(const T& r, const T& g, const T& b) {
    return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

}  // namespace facet
