#include "shade/hatch_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "shade/style_math.hpp"

namespace facet {
namespace {

// cos and sin of i·11.25°, written out so every machine rotates alike.
constexpr float kCos[kHatchOrientations] = {1.00000000f,  0.98078528f,  0.92387953f,  0.83146961f,
                                            0.70710678f,  0.55557023f,  0.38268343f,  0.19509032f,
                                            0.00000000f,  -0.19509032f, -0.38268343f, -0.55557023f,
                                            -0.70710678f, -0.83146961f, -0.92387953f, -0.98078528f};
constexpr float kSin[kHatchOrientations] = {0.00000000f, 0.19509032f, 0.38268343f, 0.55557023f,
                                            0.70710678f, 0.83146961f, 0.92387953f, 0.98078528f,
                                            1.00000000f, 0.98078528f, 0.92387953f, 0.83146961f,
                                            0.70710678f, 0.55557023f, 0.38268343f, 0.19509032f};

// A blend weight that stays 0 or 1 over the outer quarters of [0, 1] and
// ramps between: two superimposed patterns at half contrast each read as
// grey, so they share as little of the range as keeps the change smooth.
float narrow(float f) {
    return std::clamp(2.0f * f - 0.5f, 0.0f, 1.0f);
}

double wrap(double v) {
    return v - std::floor(v);
}

void add_tap(glm::vec2 rotated, int octave, float lod, float weight, float kept,
             HatchFootprint& out) {
    if (!(weight > 0.0f) || out.count >= kMaxHatchTaps) return;
    // In double: 2^octave up to 2^60 times the coordinates would overflow
    // float, and wrapping in double keeps the fraction that float has.
    const double scale = std::ldexp(1.0, octave);
    const glm::vec2 uv(static_cast<float>(wrap(rotated.x * scale)),
                       static_cast<float>(wrap(rotated.y * scale)));
    out.taps[out.count++] = {uv, lod + static_cast<float>(octave), weight, kept};
}

// How much of a chart's strokes survive its anisotropy: where the surface is
// seen edge-on, a pixel spans many tiles one way and a fraction the other,
// and strokes stretch into long streaks (the isotropic mip level cannot
// keep both widths). They fade out instead, from 3:1 to 8:1, as an
// illustrator lets hatching thin out towards a horizon.
float anisotropy_fade(glm::vec2 ddx, glm::vec2 ddy) {
    const float a = glm::dot(ddx, ddx), b = glm::dot(ddy, ddy), c = glm::dot(ddx, ddy);
    const float mean = 0.5f * (a + b);
    const float radius = std::sqrt(0.25f * (a - b) * (a - b) + c * c);
    const float major = mean + radius, minor = mean - radius;
    if (!(minor > 0.0f)) return major > 0.0f ? 0.0f : 1.0f;
    return 1.0f - smoothstep(3.0f, 8.0f, std::sqrt(major / minor));
}

}  // namespace

void add_hatch_chart(const HatchChart& chart, int tam_size, float target_lod, bool octaves,
                     HatchFootprint& out) {
    if (!(chart.weight > 0.0f)) return;
    const float footprint = std::max(glm::length(chart.ddx), glm::length(chart.ddy));
    float lod = std::log2(footprint * static_cast<float>(tam_size));
    if (!std::isfinite(lod)) lod = target_lod;  // a degenerate chart: no better guess

    // The octaves whose lods bracket the target.
    int octave = 0;
    float upper = 0.0f;  // the finer octave's share
    if (octaves) {
        const float t = std::clamp(target_lod - lod, -60.0f, 60.0f);
        const float base = std::floor(t);
        octave = static_cast<int>(base);
        upper = narrow(t - base);
    }

    const float kept = octaves ? anisotropy_fade(chart.ddx, chart.ddy) : 1.0f;

    // The two fixed orientations nearest the angle, by its place in [0, π).
    const float turn = std::numbers::pi_v<float> / kHatchOrientations;
    float position = std::fmod(chart.angle, std::numbers::pi_v<float>);
    if (!std::isfinite(position)) position = 0.0f;
    if (position < 0.0f) position += std::numbers::pi_v<float>;
    position /= turn;
    const float floor_position = std::floor(position);
    const int first = static_cast<int>(floor_position) % kHatchOrientations;
    const float next_share = narrow(position - floor_position);

    for (int o = 0; o < 2; ++o) {
        const int i = (first + o) % kHatchOrientations;
        const float share = chart.weight * (o == 0 ? 1.0f - next_share : next_share);
        if (!(share > 0.0f)) continue;
        // Rotating the coordinates by −angle turns the map's strokes, which
        // run along its first axis, to the angle.
        const glm::vec2 c = chart.coords;
        const glm::vec2 rotated(kCos[i] * c.x + kSin[i] * c.y, -kSin[i] * c.x + kCos[i] * c.y);
        add_tap(rotated, octave, lod, share * (1.0f - upper), kept, out);
        add_tap(rotated, octave + 1, lod, share * upper, kept, out);
    }
}

float hatch_coverage(const TonalArtMap& tam, float tone, const HatchFootprint& footprint) {
    float sum = 0.0f;
    for (int i = 0; i < footprint.count; ++i) {
        const HatchTap& t = footprint.taps[i];
        if (t.strokes > 0.0f) sum += t.weight * t.strokes * tam_coverage(tam, tone, t.uv, t.lod);
    }
    return sum;
}

float hatch_paper_shade(const TonalArtMap& tam, const HatchFootprint& footprint) {
    if (tam.paper.empty()) return 1.0f;
    float sum = 0.0f;
    for (int i = 0; i < footprint.count; ++i) {
        const HatchTap& t = footprint.taps[i];
        sum += t.weight * tam_paper_shade(tam, t.uv, t.lod);
    }
    return sum;
}

}  // namespace facet
