#include "core/display_transform.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "core/color.hpp"

namespace facet {
namespace {

// ACES filmic tone curve as fitted by Krzysztof Narkowicz ("ACES Filmic
// Tone Mapping Curve", 2015): a rational fit of the RRT+ODT luminance
// response. His fit expects its input scaled by 0.6 so that scene middle
// grey lands where the reference transform puts it.
float aces_curve(float x) {
    x *= 0.6f;
    const float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return std::clamp(y, 0.0f, 1.0f);
}

// An AgX-like filmic curve, our own: the value is encoded as stops around
// middle grey (0.18) over [-10, +6.5] stops, where film's response lives,
// passed through a logistic S-curve pinned to 0 and 1 at the ends of that
// range, and the result (a display value) turned back to linear for the
// sRGB encoder. Before the curve each channel is pulled 15% toward the
// pixel's mean ("inset"), so that bright saturated colours move toward
// white instead of skewing hue as each channel clips on its own.
constexpr float kMinStops = -10.0f, kMaxStops = 6.5f;
constexpr float kContrast = 9.0f;  // slope of the logistic over the unit range
float logistic(float t) {
    return 1.0f / (1.0f + std::exp(-kContrast * (t - 0.606f)));
}

float filmic_curve(float x) {
    if (!(x > 0.0f)) return 0.0f;
    const float stops = std::log2(x / 0.18f);
    const float t = std::clamp((stops - kMinStops) / (kMaxStops - kMinStops), 0.0f, 1.0f);
    // The curve's ends, computed once: this runs per channel of every pixel.
    static const float lo = logistic(0.0f), hi = logistic(1.0f);
    const float display = (logistic(t) - lo) / (hi - lo);
    return srgb_to_linear(display);
}

// Khronos PBR Neutral (the Khronos 3D Commerce group's specification, 2024): made
// for product images, so that a base colour up to about 0.8 comes out as
// authored. Dark values lose a small offset that keeps near-black from
// looking lifted (0.04, blended in below 0.08 as x - 6.25 x^2); then only
// colours whose largest channel passes 0.76 are compressed, all three by
// the same factor so the hue stays, toward a peak that approaches 1, and
// the brightest are desaturated toward white by how much was compressed.
glm::vec3 khronos_neutral(glm::vec3 c) {
    constexpr float kStartCompression = 0.8f - 0.04f, kDesaturation = 0.15f;
    const float lowest = std::min(c.r, std::min(c.g, c.b));
    const float offset = lowest < 0.08f ? lowest - 6.25f * lowest * lowest : 0.04f;
    c -= offset;
    const float peak = std::max(c.r, std::max(c.g, c.b));
    if (peak < kStartCompression) return c;
    constexpr float d = 1.0f - kStartCompression;
    const float new_peak = 1.0f - d * d / (peak + d - kStartCompression);
    c *= new_peak / peak;
    const float g = 1.0f - 1.0f / (kDesaturation * (peak - new_peak) + 1.0f);
    return c + (glm::vec3(new_peak) - c) * g;
}

// AgX, Blender 4's default view transform: Troy Sobotka's image formation as
// Eary Chow built it for Blender (the AgX_LUT_Gen scripts, AgXBaseRec2020.py
// and AgXBasesRGB.py, that generate Blender's AgX_Base_sRGB.cube). Blender
// reads the result from a 3D LUT; we evaluate the same steps directly, so
// there is no table to ship and no interpolation error. The steps, in
// agx_formation below: Rec.709 to Rec.2020; the inset matrix; log2 over
// -10..+6.5 stops around 0.18; the sigmoid, giving a value encoded with a
// 2.4 power; decoded, 60% of the hue from before the curve restored; the
// outset matrix; Rec.2020 to Rec.709; negatives offset away; encoded with
// 1/2.4 and clipped to [0, 1]. That last value is the code Blender writes
// to the file, so we return it decoded with the sRGB curve: our sRGB
// encoder then writes the same code, as with the filmic curve above.
namespace agx {

// Row-major 3x3 from published coefficients; glm stores columns.
glm::dmat3 from_rows(glm::dvec3 r0, glm::dvec3 r1, glm::dvec3 r2) {
    return glm::transpose(glm::dmat3(r0, r1, r2));
}

struct Matrices {
    glm::mat3 to_rec2020, inset, outset, to_rec709;
};

// Computed once, in double, from the published values.
const Matrices& matrices() {
    static const Matrices m = [] {
        // Linear Rec.709 to Rec.2020, from the two sets of primaries and D65
        // (ITU-R BT.2087-0 prints it to 4 decimals).
        const glm::dmat3 to_2020 =
            from_rows({0.62740389593469903, 0.32928303837788381, 0.043313065687417218},
                      {0.069097289358231992, 0.91954039507545904, 0.011362315566309157},
                      {0.016391438875150228, 0.088013307877225777, 0.89559525324762401});
        // Sobotka's SB2383 generator with rotate [3, -1, -2], inset [0.4, 0.22,
        // 0.13]: it pulls the primaries in (and turns them a little) so that
        // bright colours travel toward white along a smooth path.
        const glm::dmat3 inset =
            from_rows({0.856627153315983, 0.0951212405381588, 0.0482516061458583},
                      {0.137318972929847, 0.761241990602591, 0.101439036467562},
                      {0.11189821299995, 0.0767994186031903, 0.811302368396859});
        // The outset is the inverse of SB2383's matrix for rotate [0, 0, 0],
        // inset [0.4, 0.22, 0.04]: it gives back most of the chroma.
        const glm::dmat3 outset_inverse =
            from_rows({0.899796955911611, 0.0871996192028351, 0.013003424885555},
                      {0.11142098895748, 0.875575586156966, 0.0130034248855548},
                      {0.11142098895748, 0.0871996192028349, 0.801379391839686});
        return Matrices{glm::mat3(to_2020), glm::mat3(inset),
                        glm::mat3(glm::inverse(outset_inverse)), glm::mat3(glm::inverse(to_2020))};
    }();
    return m;
}

// Every matrix here maps white to white (its rows sum to 1), so it is applied
// as c.g plus the matrix times the difference from c.g: the same value, but
// an exact grey stays exactly grey however the float coefficients round.
glm::vec3 white_preserving(const glm::mat3& m, glm::vec3 c) {
    return glm::vec3(c.g) + m * (c - glm::vec3(c.g));
}

// The sigmoid of AgX (Jed Smith's tunable sigmoid, which Sobotka's scripts
// use): a straight line of slope 2.4 through the pivot, continued on each
// side by the curve s * u / (1 + u^p)^(1/p), which leaves with the line's
// slope and flattens; each side's scale s makes it pass through (0, 0) and
// (1, 1). Blender's pivot: x = 10/16.5 (middle grey in the log range), y =
// 0.18^(1/2.4) (middle grey, encoded with the 2.4 power the curve outputs).
constexpr double kPivotX = 10.0 / 16.5, kSlope = 2.4, kPower = 1.5;

struct Sigmoid {
    double pivot_y, toe_scale, shoulder_scale;
};

// The scale s for which the side reaches `rise` after `run`: solve
// s * h(slope * run / s) = rise for h(u) = u / (1 + u^p)^(1/p).
double side_scale(double run, double rise) {
    const double a = kSlope * run;
    return a / std::pow(std::pow(a / rise, kPower) - 1.0, 1.0 / kPower);
}

const Sigmoid& sigmoid_constants() {
    static const Sigmoid s = [] {
        const double y = std::pow(0.18, 1.0 / 2.4);
        return Sigmoid{y, side_scale(kPivotX, y), side_scale(1.0 - kPivotX, 1.0 - y)};
    }();
    return s;
}

float sigmoid(float x) {
    if (!(x > 0.0f)) return 0.0f;
    const Sigmoid& s = sigmoid_constants();
    const float d = x - static_cast<float>(kPivotX);
    const float scale = static_cast<float>(d < 0.0f ? s.toe_scale : s.shoulder_scale);
    const float u = static_cast<float>(kSlope) * std::abs(d) / scale;
    const float p = static_cast<float>(kPower);
    const float bend = u / std::pow(1.0f + std::pow(u, p), 1.0f / p);
    // Rounding can leave the toe a hair below 0 near x = 0, where the 2.4
    // power that follows has no real value.
    return std::max(static_cast<float>(s.pivot_y) + std::copysign(scale * bend, d), 0.0f);
}

// Value to the curve's input: log2 stops around 0.18 over [-10, +6.5]
// (log2 of the value from -12.47393 to 4.026069) mapped to [0, 1]. Blender's
// LUT takes its input from -10 to +15 stops, so the shoulder goes on past 1
// up to +15 stops and the final clip decides; below -10 stops is black.
float log_encode(float x) {
    if (!(x > 0.0f)) return 0.0f;
    const float t = (std::log2(x / 0.18f) + 10.0f) / 16.5f;
    return std::clamp(t, 0.0f, 25.0f / 16.5f);
}

// HSV hue in turns [0, 1); negative for a grey, which has none.
float hue(glm::vec3 c) {
    const float hi = std::max(c.r, std::max(c.g, c.b));
    const float chroma = hi - std::min(c.r, std::min(c.g, c.b));
    if (!(chroma > 0.0f)) return -1.0f;
    float sixths;
    if (hi == c.r)
        sixths = (c.g - c.b) / chroma + (c.g < c.b ? 6.0f : 0.0f);
    else if (hi == c.g)
        sixths = (c.b - c.r) / chroma + 2.0f;
    else
        sixths = (c.r - c.g) / chroma + 4.0f;
    return sixths / 6.0f;
}

// `c` with HSV hue `turns`, its value (largest channel) and its chroma
// (largest minus smallest) kept.
glm::vec3 with_hue(glm::vec3 c, float turns) {
    const float hi = std::max(c.r, std::max(c.g, c.b));
    const float lo = std::min(c.r, std::min(c.g, c.b));
    const float sixths = (turns - std::floor(turns)) * 6.0f;
    const int sector = std::min(static_cast<int>(sixths), 5);
    const float f = sixths - static_cast<float>(sector);
    const float rising = lo + (hi - lo) * f, falling = hi - (hi - lo) * f;
    switch (sector) {
        case 0:
            return {hi, rising, lo};
        case 1:
            return {falling, hi, lo};
        case 2:
            return {lo, hi, rising};
        case 3:
            return {lo, falling, hi};
        case 4:
            return {rising, lo, hi};
        default:
            return {hi, lo, falling};
    }
}

// Blender keeps 40% of the hue shift the per-channel curve makes and
// restores the rest. Blender's script interpolates the hue numbers; we take
// the difference the short way round the circle, which is the same while
// both hues are within half a turn (the curve keeps the channels' order, so
// they are) and avoids a swing through the opposite hue when they straddle
// red.
glm::vec3 restore_hue(glm::vec3 formed, float before) {
    const float after = hue(formed);
    if (before < 0.0f || after < 0.0f) return formed;
    float shift = after - before;
    shift -= std::round(shift);
    return with_hue(formed, before + 0.4f * shift);
}

// A colour the outset pushed outside Rec.709 has a negative channel: lift
// all three by it (toward white, keeping the hue), then scale back so the
// luminance does not rise. A simpler form of Blender's lower guard rail.
glm::vec3 offset_negatives(glm::vec3 c) {
    const float lowest = std::min(c.r, std::min(c.g, c.b));
    if (!(lowest < 0.0f)) return c;
    const float before = rec709_luminance(c.r, c.g, c.b);
    c -= lowest;
    const float after = rec709_luminance(c.r, c.g, c.b);
    if (after > before) c *= std::max(before, 0.0f) / after;
    return c;
}

glm::vec3 agx_formation(glm::vec3 c) {
    const Matrices& m = matrices();
    c = white_preserving(m.inset, white_preserving(m.to_rec2020, glm::max(c, glm::vec3(0.0f))));
    const float hue_before = hue(c);
    glm::vec3 formed;
    for (int i = 0; i < 3; ++i) formed[i] = std::pow(sigmoid(log_encode(c[i])), 2.4f);
    formed = restore_hue(formed, hue_before);
    c = white_preserving(m.to_rec709, white_preserving(m.outset, formed));
    c = offset_negatives(c);
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = srgb_to_linear(std::pow(std::clamp(c[i], 0.0f, 1.0f), 1.0f / 2.4f));
    return out;
}

}  // namespace agx

// The largest value a curve is given: every curve has reached its white
// long before (ACES by 13, the filmic curves by 0.18 * 2^15), and below it
// their arithmetic stays finite (ACES's square up to 1.8e19; the inset's
// sums and differences of three channels). Infinity and larger values are
// taken as this, so that they map to white instead of to NaN.
constexpr float kLargestToned = 1e18f;

glm::vec3 tone(glm::vec3 c, Tonemap tonemap) {
    for (int i = 0; i < 3; ++i) c[i] = c[i] > kLargestToned ? kLargestToned : c[i];  // NaN stays
    switch (tonemap) {
        case Tonemap::none:
            return c;
        case Tonemap::aces:
            return {aces_curve(c.r), aces_curve(c.g), aces_curve(c.b)};
        case Tonemap::filmic: {
            const float mean = (c.r + c.g + c.b) / 3.0f;
            c += (glm::vec3(mean) - c) * 0.15f;
            return {filmic_curve(c.r), filmic_curve(c.g), filmic_curve(c.b)};
        }
        case Tonemap::neutral:
            return khronos_neutral(c);
        case Tonemap::agx:
            return agx::agx_formation(c);
    }
    return c;
}

}  // namespace

float exposure_gain(const DisplayTransform& transform) {
    // exp2 of a whole number of stops is exact, so +1 doubles exactly.
    return std::exp2(transform.exposure);
}

glm::vec4 display_color(const glm::vec4& premultiplied, const DisplayTransform& transform,
                        float gain) {
    const float a = premultiplied.a;
    if (!(a > 0.0f) || transform.is_identity()) return premultiplied;
    const glm::vec3 straight = glm::vec3(premultiplied) / a * gain;
    return {tone(straight, transform.tonemap) * a, a};
}

glm::vec4 display_color(const glm::vec4& premultiplied, const DisplayTransform& transform) {
    return display_color(premultiplied, transform, exposure_gain(transform));
}

ColorImage apply_display_transform(const ColorImage& image, const DisplayTransform& transform) {
    const float gain = exposure_gain(transform);
    ColorImage out = image;
    for (glm::vec4& c : out.pixels) c = display_color(c, transform, gain);
    return out;
}

uint8_t display_byte(double linear) {
    const double unit = linear > 0.0 ? std::min(linear, 1.0) : 0.0;
    return static_cast<uint8_t>(std::lround(linear_to_srgb(unit) * 255.0));
}

uint8_t narrow_to_byte(uint16_t v) {
    return static_cast<uint8_t>((static_cast<uint32_t>(v) * 255u + 32767u) / 65535u);
}

HalfColorImage apply_display_transform(const HalfColorImage& image,
                                       const DisplayTransform& transform) {
    const float gain = exposure_gain(transform);
    HalfColorImage out = image;
    for (Rgba16F& c : out.pixels) c = to_half(display_color(to_float(c), transform, gain));
    return out;
}

}  // namespace facet
