#pragma once
// Toon (cel) shading after Lake, Marshall, Harris & Blackstein 2000,
// "Stylized Rendering Techniques for Scalable Real-Time 3D Animation": the
// key light's n·l looks up a few flat bands (their 1-D texture), here a
// list of thresholds or a colour ramp; a hard-edged highlight; and a rim
// light on the parts that turn away from the viewer. Band edges can be
// softened with a smoothstep so they do not alias into stairs. The seed-000
// survey (docs/references.md, §1.5.2) describes the two-colour case with one threshold.
//
// Thresholds and ramp positions are in n·l units, [−1, 1], so a band can
// start on the shadowed side. The band values replace the light: the key
// light's colour does not scale them. Several lights: bands follow the key
// light, lights[0] (see shade/palette_style.hpp for why); every light adds
// its own highlight, scaled by its radiance.
//
// Per pixel (n, v unit; lights from sample_light):
//   glm::vec3 c = toon_diffuse(style, albedo, dot3(n, lights[0].to_light));
//   for (const LightSample& l : lights) c += toon_specular(style, n, v, l);
//   c += toon_rim(style, n, v);
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "shade/light_sample.hpp"
#include "shade/style_math.hpp"
#include "shade/stylised_light.hpp"

namespace facet {

// One band (or ramp stop): from `threshold` upwards the value is `value`,
// an intensity (grey) or a colour.
struct ToonBand {
    float threshold = 0.0f;
    glm::vec3 value{1.0f};
};

enum class ToonMode {
    bands,  // piecewise constant: the band with the highest threshold <= n·l
    ramp,   // piecewise linear between the stops, constant beyond the ends
};

struct ToonStyle {
    // Sorted by threshold, ascending. The first band also covers everything
    // below its threshold.
    std::vector<ToonBand> bands{
        {-1.0f, glm::vec3(0.35f)}, {0.0f, glm::vec3(0.7f)}, {0.5f, glm::vec3(1.0f)}};
    ToonMode mode = ToonMode::bands;
    float band_softness = 0.0f;   // width of each band edge in n·l units; 0 = hard
    bool multiply_albedo = true;  // band values scale the object colour; else they are the colour

    // Highlight: on where (n·h)^shininess >= specular_threshold.
    glm::vec3 specular_color{1.0f};  // black turns it off
    float shininess = 32.0f;
    float specular_threshold = 0.5f;
    float specular_softness = 0.0f;  // edge width, in units of (n·h)^shininess

    // Rim: on where (1 − n·v)^rim_power >= rim_threshold.
    glm::vec3 rim_color{0.0f};  // black (the default) turns it off
    float rim_power = 2.0f;
    float rim_threshold = 0.5f;
    float rim_softness = 0.0f;  // edge width, in units of (1 − n·v)^rim_power
};

// The band or ramp value at x (an n·l).
inline glm::vec3 toon_band_value(std::span<const ToonBand> bands, ToonMode mode, float softness,
                                 float x) {
    if (bands.empty()) return glm::vec3(1.0f);
    glm::vec3 value = bands[0].value;
    if (mode == ToonMode::bands) {
        // Each higher band takes over at its threshold: a mix by a step (or
        // a smoothstep), so there is no search and no branch per pixel.
        for (size_t i = 1; i < bands.size(); ++i)
            value += (bands[i].value - value) * band_edge(x, bands[i].threshold, softness);
        return value;
    }
    for (size_t i = 1; i < bands.size(); ++i) {
        const float lo = bands[i - 1].threshold, hi = bands[i].threshold;
        const float t = hi > lo ? saturate((x - lo) / (hi - lo)) : (x >= hi ? 1.0f : 0.0f);
        value += (bands[i].value - value) * t;
    }
    return value;
}

inline glm::vec3 toon_diffuse(const ToonStyle& style, const glm::vec3& albedo, float n_dot_l) {
    const glm::vec3 v = toon_band_value(style.bands, style.mode, style.band_softness, n_dot_l);
    return style.multiply_albedo ? albedo * v : v;
}

// A hard highlight: Blinn's (n·h)^shininess through a threshold, so its
// size follows shininess and threshold while its edge stays crisp.
inline glm::vec3 toon_specular(const ToonStyle& style, const glm::vec3& n, const glm::vec3& v,
                               const LightSample& light) {
    if (!(dot3(n, light.to_light) > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 h = normalise_or(light.to_light + v, n);
    const float power = pow_unit(dot3(n, h), style.shininess);
    const float on = band_edge(power, style.specular_threshold, style.specular_softness);
    return on * (style.specular_color * light.radiance);
}

// Rim light (1 − n·v)^power through a threshold: it outlines the parts of
// a silhouette that turn away from the viewer, whatever the lights do.
inline glm::vec3 toon_rim(const ToonStyle& style, const glm::vec3& n, const glm::vec3& v) {
    const float facing = saturate(dot3(n, v));
    const float rim = pow_unit(1.0f - facing, style.rim_power);
    return band_edge(rim, style.rim_threshold, style.rim_softness) * style.rim_color;
}

// The whole toon model at one point (n, v unit): bands from the key light,
// the rim light, then every light's highlight.
inline glm::vec3 shade_toon(const ToonStyle& style, const glm::vec3& albedo,
                            const glm::vec3& position, const glm::vec3& n, const glm::vec3& v,
                            std::span<const ShadeLight> lights, bool receives_shadows,
                            float highlight_strength) {
    const float n_dot_l = key_light_cosine(lights, position, n, receives_shadows);
    glm::vec3 c = toon_diffuse(style, albedo, n_dot_l) + toon_rim(style, n, v);
    add_highlights(c, lights, position, n, receives_shadows, highlight_strength,
                   [&](const LightSample& l) { return toon_specular(style, n, v, l); });
    return c;
}

}  // namespace facet
