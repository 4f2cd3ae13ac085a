#pragma once
// Gooch, Gooch, Shirley & Cohen 1998, "A Non-Photorealistic Lighting Model
// for Automatic Technical Illustration": shade from a cool colour facing
// away from the light to a warm one facing it, each mixing a fixed hue with
// the object's diffuse colour, plus a Phong highlight.
//
//   k_cool = k_blue + alpha·k_d,   k_blue = (0, 0, b)
//   k_warm = k_yellow + beta·k_d,  k_yellow = (y, y, 0)
//   t = (1 + n·l)/2,  I = t·k_warm + (1 − t)·k_cool
//
// The paper prints the blend with (1 + l·n)/2 weighting k_cool, which gives
// its intended picture (warm towards the light) only for l pointing away
// from the light; here l points towards it, as everywhere in facet.
// Several lights: the blend uses the key light, lights[0] (the paper
// assumes one light; see shade/palette_style.hpp for why the first and not
// a sum); every light adds its own highlight, scaled by its radiance.
//
// Per pixel (n, v unit; lights from sample_light; `palette` has ambient 0
// and cels 0):
//   glm::vec3 c = seed_palette(palette, kd, dot3(n, lights[0].to_light)).color;
//   for (const LightSample& l : lights) c += gooch_highlight(style, n, v, l);
#include <span>

#include <glm/vec3.hpp>

#include "shade/light_sample.hpp"
#include "shade/palette_style.hpp"
#include "shade/style_math.hpp"
#include "shade/stylised_light.hpp"

namespace facet {

// The diffuse blend is the palette model's (shade/palette_style.hpp,
// seed_palette) with the paper's colours (k_blue = shadow colour, k_yellow =
// lit colour), no ambient term and no cels; this file adds the highlight.
struct GoochStyle {
    glm::vec3 highlight_color{1.0f};  // the paper's highlights are white
    float shininess = 32.0f;          // not given in the paper
};

// Phong's highlight (r·v)^s with r = 2(n·l)n − l, only where n·l > 0.
inline glm::vec3 gooch_highlight(const GoochStyle& style, const glm::vec3& n, const glm::vec3& v,
                                 const LightSample& light) {
    const float n_dot_l = dot3(n, light.to_light);
    if (!(n_dot_l > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 r = (2.0f * n_dot_l) * n - light.to_light;
    const float power = pow_unit(dot3(r, v), style.shininess);
    return power * (style.highlight_color * light.radiance);
}

// The whole Gooch model at one point (n, v unit; kd the object colour):
// the palette blend of `palette`'s two colours without ambient or cels,
// then every light's highlight.
inline glm::vec3 shade_gooch(const GoochStyle& style, const PaletteStyle& palette,
                             const glm::vec3& kd, const glm::vec3& position, const glm::vec3& n,
                             const glm::vec3& v, std::span<const ShadeLight> lights,
                             bool receives_shadows, float highlight_strength) {
    PaletteStyle blend = palette;
    blend.ambient = 0;
    blend.cels = 0;
    glm::vec3 c =
        seed_palette(blend, kd, key_light_cosine(lights, position, n, receives_shadows)).color;
    add_highlights(c, lights, position, n, receives_shadows, highlight_strength,
                   [&](const LightSample& l) { return gooch_highlight(style, n, v, l); });
    return c;
}

}  // namespace facet
