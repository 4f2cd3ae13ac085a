#pragma once
// Light colours given as a colour temperature (docs/references.md: the seed-001 light's
// "spectral characteristics"): the colour of a black body at that
// temperature, as linear sRGB.
namespace facet {

// The range the Planckian-locus fit below holds for, in kelvin.
inline constexpr double kMinKelvin = 1667;
inline constexpr double kMaxKelvin = 25000;

struct LinearRgb {
    double r, g, b;
};

// A black body's colour at `kelvin` (clamped to [kMinKelvin, kMaxKelvin]):
// CIE 1931 xy on the Planckian locus by the cubic fit of Kang et al. 2002
// ("Design of advanced color temperature control system for HDTV
// applications", J. Korean Phys. Soc. 41(6); also Kim et al., US patent
// 7,024,034), then XYZ with Y = 1, then linear sRGB through the IEC 61966-2-1
// matrix (D65 white). Negative components (out of the sRGB gamut) become 0,
// and the result is scaled so that its largest component is 1: brightness
// is the light's `intensity`, not its temperature.
LinearRgb kelvin_to_linear_srgb(double kelvin);

}  // namespace facet
