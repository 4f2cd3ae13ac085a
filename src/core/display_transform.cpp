#include "core/display_transform.hpp"

#include <algorithm>
#include <cmath>

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

glm::vec3 tone(glm::vec3 c, Tonemap tonemap) {
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
    }
    return c;
}

}  // namespace

Tonemap tonemap_from_name(std::string_view name) {
    if (name == "aces") return Tonemap::aces;
    if (name == "filmic") return Tonemap::filmic;
    if (name == "neutral") return Tonemap::neutral;
    return Tonemap::none;
}

const char* tonemap_name(Tonemap tonemap) {
    switch (tonemap) {
        case Tonemap::aces:
            return "aces";
        case Tonemap::filmic:
            return "filmic";
        case Tonemap::neutral:
            return "neutral";
        case Tonemap::none:
            break;
    }
    return "none";
}

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
