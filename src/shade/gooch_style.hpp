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
// Per pixel (n, v unit; lights from sample_light):
//   glm::vec3 c = gooch_diffuse(style, kd, dot3(n, lights[0].to_light));
//   for (const LightSample& l : lights) c += gooch_highlight(style, n, v, l);
#include <glm/vec3.hpp>

#include "shade/light_sample.hpp"
#include "shade/style_math.hpp"

namespace facet {

struct GoochStyle {
    float blue = 0.4f;                // b, the paper's value
    float yellow = 0.4f;              // y, the paper's value
    float alpha = 0.2f;               // the paper's value
    float beta = 0.6f;                // the paper's value
    glm::vec3 highlight_color{1.0f};  // the paper's highlights are white
    float shininess = 32.0f;          // not given in the paper
};

inline glm::vec3 gooch_cool(const GoochStyle& style, const glm::vec3& kd) {
    return glm::vec3(0.0f, 0.0f, style.blue) + style.alpha * kd;
}

inline glm::vec3 gooch_warm(const GoochStyle& style, const glm::vec3& kd) {
    return glm::vec3(style.yellow, style.yellow, 0.0f) + style.beta * kd;
}

// The cool-to-warm blend; `n_dot_l` is the key light's cosine, any sign.
inline glm::vec3 gooch_diffuse(const GoochStyle& style, const glm::vec3& kd, float n_dot_l) {
    const float t = (1.0f + std::clamp(n_dot_l, -1.0f, 1.0f)) * 0.5f;
    return t * gooch_warm(style, kd) + (1.0f - t) * gooch_cool(style, kd);
}

// Phong's highlight (r·v)^s with r = 2(n·l)n − l, only where n·l > 0.
inline glm::vec3 gooch_highlight(const GoochStyle& style, const glm::vec3& n, const glm::vec3& v,
                                 const LightSample& light) {
    const float n_dot_l = dot3(n, light.to_light);
    if (!(n_dot_l > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 r = (2.0f * n_dot_l) * n - light.to_light;
    const float power = pow_unit(dot3(r, v), style.shininess);
    return power * (style.highlight_color * light.radiance);
}

}  // namespace facet
