#pragma once
// The seed-000 stylisation method (docs/references.md, seed 000 §3.2.4 and
// its appendix's draw_pixel): Gooch's cool-to-warm blend with two free
// palette colours, colour quantised to N cels, hatching in the dark cels,
// and a highlight added last.
//
// Where facet departs from the seed's text or listing, and why:
//  - |c| is the Euclidean length of the RGB vector (the listing's
//    vec3_length), so white (1,1,1) has |c| = sqrt(3).
//  - q = round(L·N)/N and c' = c·q, as the seed's text and listing both
//    say (the listing truncates L·N with an int cast; facet rounds, as the
//    text does). `cel_color: keep_hue` gives c' = c·q/L instead, which keeps
//    |c'| = q exactly and the hue: the seed's c·q scales the colour by about
//    L·q, so a bright colour brightens further and a dark one darkens.
//  - The listing weights the shadow colour by (1 + n·l)/2, as Gooch 1998
//    prints its formula for a light vector pointing away from the light;
//    with l pointing towards the light, as here, the lit colour gets
//    t = (1 + n·l)/2, which is what the seed's text describes ("the closer
//    to the light, the warmer").
//  - The listing's intensity() for the hatching thresholds is not given.
//    facet uses tone = q / sqrt(3), clamped to 1 (q = |c| unquantised):
//    for a grey (g,g,g) this is g, and it is constant over a cel in both
//    cel modes, so hatching bands line up with the cels.
//  - The listing adds the stroke texture to the colour; `hatching.blend:
//    add` does that (add_hatching), and the palette preset uses it. The
//    default, `ink`, blends towards the ink instead (apply_hatching).
//
// Several lights: the palette term uses the key light, lights[0], only.
// The method maps one direction to a two-colour palette: summing t over
// lights leaves [0, 1] and the palette colours stop being its ends, and
// averaging flattens the terminator. The first light is chosen, not the
// strongest, because the strongest can change from frame to frame as point
// lights move, and the whole palette would jump. Light colours do not tint
// the palette term (the palette colours stand in for them, as in Gooch's
// method); every light adds its own highlight, scaled by its radiance.
//
// Per pixel (n, v unit; lights from sample_light; k the object colour):
//   PaletteShading p = seed_palette(style, k, dot3(n, lights[0].to_light));
//   float coverage = tam_coverage(tam, palette_hatch_tone(style, p.tone), uv, lod);
//   glm::vec3 c = apply_hatching(p.color, palette_ink(style, k), coverage);
//   for (const LightSample& l : lights) c += seed_specular(style, k, n, v, l);
#include <cmath>
#include <span>

#include <glm/vec3.hpp>

#include "shade/light_sample.hpp"
#include "shade/style_math.hpp"
#include "shade/stylised_light.hpp"

namespace facet {

struct PaletteStyle {
    glm::vec3 shadow_color{0.0f, 0.0f, 0.4f};  // c_shadow, the side away from the light
    glm::vec3 lit_color{0.4f, 0.4f, 0.0f};     // c_lit, the side facing it
    float alpha = 0.2f;                        // share of the object colour in the shadow colour
    float beta = 0.6f;                         // share of the object colour in the lit colour
    float ambient = 0.2f;                      // a (the seed's 0.2)
    int cels = 4;                              // N; 0 or less keeps the colour unquantised
    bool cels_keep_hue = false;                // c' = c·q/L instead of the seed's c·q
    float specular = 1.0f;                     // highlight scale (the seed: 1)
    float shininess = 32.0f;                   // the seed's per-material exponent
    float hatch_below = 0.5f;                  // tone under which strokes appear (the seed: 0.5)
    float hatch_ink = 0.25f;  // strokes are drawn in k * hatch_ink ("tinted by the object")
};

// The colour before hatching and highlights, and its tone for hatching.
struct PaletteShading {
    glm::vec3 color{0.0f};  // c'
    float tone = 0.0f;      // q / sqrt(3), clamped to [0, 1]
};

inline float color_length(const glm::vec3& c) {
    return std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
}

// q = round(L·N)/N for L = |c|: the cel's level, a multiple of 1/N; L
// itself when N <= 0 (no quantisation).
inline float cel_level(const glm::vec3& c, int cels) {
    const float length = color_length(c);
    if (cels <= 0) return length;
    const float n = static_cast<float>(cels);
    return std::floor(length * n + 0.5f) / n;
}

// The seed's c' = c·q; with `keep_hue`, c' = c·q/L, whose length is q and
// whose hue (the ratios r:g:b) is c's. Black stays black; N <= 0 returns c.
inline glm::vec3 quantise_cels(const glm::vec3& c, int cels, bool keep_hue = false) {
    const float length = color_length(c);
    if (cels <= 0 || !(length > 0.0f)) return c;
    const float q = cel_level(c, cels);
    return keep_hue ? c * (q / length) : c * q;
}

// Seed 000 §3.2.4: ambient a·k plus the palette blend by t = (1 + n·l)/2,
// quantised to cels. `n_dot_l` is the key light's cosine, any sign.
inline PaletteShading seed_palette(const PaletteStyle& style, const glm::vec3& k, float n_dot_l) {
    const float t = (1.0f + std::clamp(n_dot_l, -1.0f, 1.0f)) * 0.5f;
    const glm::vec3 cool = style.shadow_color + style.alpha * k;
    const glm::vec3 warm = style.lit_color + style.beta * k;
    const glm::vec3 c = style.ambient * k + (t * warm + (1.0f - t) * cool);
    const glm::vec3 celled = quantise_cels(c, style.cels, style.cels_keep_hue);
    return {celled, std::min(cel_level(c, style.cels) * (1.0f / std::sqrt(3.0f)), 1.0f)};
}

// The seed hatches below intensity 0.5 (lighter strokes) and below 0.25
// (dense strokes). Generalised: tones in [0, hatch_below) map linearly onto
// a tonal art map's whole range [0, 1), and anything at or above
// hatch_below maps to 1, which draws no strokes.
inline float palette_hatch_tone(const PaletteStyle& style, float tone) {
    if (!(style.hatch_below > 0.0f)) return 1.0f;
    return saturate(tone / style.hatch_below);
}

inline glm::vec3 palette_ink(const PaletteStyle& style, const glm::vec3& k) {
    return k * style.hatch_ink;
}

// Strokes laid over the colour: `coverage` in [0, 1] from a tonal art map.
inline glm::vec3 apply_hatching(const glm::vec3& color, const glm::vec3& ink, float coverage) {
    return color + (ink - color) * coverage;
}

// Seed 000's way: the strokes' colour (ink x coverage) added to the colour.
inline glm::vec3 add_hatching(const glm::vec3& color, const glm::vec3& ink, float coverage) {
    return color + ink * coverage;
}

// Blinn's half vector h = normalise(l + v); highlight k·(n·h)^shininess
// (the seed's formula), scaled by the light's radiance so that several
// lights add up; with one white light of intensity 1 it is the seed's term.
// Nothing where n·l <= 0: the seed's listing has no such test, but without
// it grazing back-lit pixels get a highlight from a light they cannot see.
inline glm::vec3 seed_specular(const PaletteStyle& style, const glm::vec3& k, const glm::vec3& n,
                               const glm::vec3& v, const LightSample& light) {
    if (!(dot3(n, light.to_light) > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 h = normalise_or(light.to_light + v, n);
    const float power = pow_unit(dot3(n, h), style.shininess);
    return (style.specular * power) * (k * light.radiance);
}

// The whole palette model at one point (n, v unit; k the object colour):
// the palette term from the key light, then every light's highlight.
// `tone` gets the cel's tone, for hatching.
inline glm::vec3 shade_palette(const PaletteStyle& style, const glm::vec3& k,
                               const glm::vec3& position, const glm::vec3& n, const glm::vec3& v,
                               std::span<const ShadeLight> lights, bool receives_shadows,
                               float highlight_strength, float& tone) {
    const PaletteShading p =
        seed_palette(style, k, key_light_cosine(lights, position, n, receives_shadows));
    tone = p.tone;
    glm::vec3 c = p.color;
    add_highlights(c, lights, position, n, receives_shadows, highlight_strength,
                   [&](const LightSample& l) { return seed_specular(style, k, n, v, l); });
    return c;
}

}  // namespace facet
