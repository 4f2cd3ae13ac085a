#pragma once
// How the stylised models (palette, Gooch, toon) see the lights: one key
// light drives their diffuse term, and every light adds its own highlight.
// Shadows take part through the key light's n·l, darkened towards -1, so
// toon styles get a hard shadow band (docs/styles.md, "Light").
#include <span>

#include <glm/vec3.hpp>

#include "shade/light_sample.hpp"
#include "shade/shadow_map.hpp"

namespace facet {

// The key light is the first light that is not ambient (see
// shade/palette_style.hpp for why the first and not the strongest). Its n·l
// at `position`, shadow folded in; 0, the middle of the palette, when the
// scene has no such light. n unit.
inline float key_light_cosine(std::span<const ShadeLight> lights, const glm::vec3& position,
                              const glm::vec3& n, bool receives_shadows) {
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) continue;
        const LightSample key = sample_light(light, position);
        const float visibility = receives_shadows ? light_visibility(light, position, n) : 1.0f;
        return -1.0f + (dot3(n, key.to_light) + 1.0f) * visibility;
    }
    return 0.0f;
}

// Adds highlight(sample) to `color` for each light that reaches
// `position`, in light order, each sample's radiance scaled by its shadow
// visibility.
// `strength` scales them all: the material's specular over the default
// material's (kDefaultSpecular), so a default material gets the style's
// highlight as designed, a matte one (specular 0) none.
template <typename Highlight>
void add_highlights(glm::vec3& color, std::span<const ShadeLight> lights, const glm::vec3& position,
                    const glm::vec3& n, bool receives_shadows, float strength,
                    Highlight highlight) {
    if (!(strength > 0.0f)) return;
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) continue;
        LightSample l = sample_light(light, position);
        if (!(l.radiance.x > 0 || l.radiance.y > 0 || l.radiance.z > 0)) continue;
        l.radiance *= receives_shadows ? light_visibility(light, position, n) : 1.0f;
        color += strength * highlight(l);
    }
}

}  // namespace facet
