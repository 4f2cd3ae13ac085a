#pragma once
// glTF's metallic-roughness material as the Phong family reads it (the
// `phong`, `blinn_phong`, `flat` and `gouraud` models, and the presets
// built on them): one conversion, documented with its sources in
// docs/styles.md, "PBR materials under every preset".
//
// The metal-rough model splits a surface's light into a diffuse part of
// colour base * (1 - metallic) and a specular part whose colour at normal
// incidence is f0 = mix(f0_dielectric, base, metallic) (glTF 2.0,
// Appendix B). The Phong family has the same two parts: its albedo takes
// the first, its highlight's colour the second, and the highlight's
// exponent and strength come from the roughness:
// - the exponent n = 2 / alpha^2 - 2 with alpha = roughness^2, the
//   Blinn-Phong lobe of the same width as a Beckmann lobe of slope alpha
//   (Walter et al. 2007, "Microfacet Models for Refraction through Rough
//   Surfaces", eq. 33); roughness_exponent, assets/mesh.hpp;
// - the strength (n + 8) / 8, the normalisation that makes a Blinn-Phong
//   lobe reflect what its Fresnel colour says whatever its width
//   (Akenine-Moller, Haines and Hoffman, "Real-Time Rendering", 3rd ed.,
//   section 7.6: (n + 8) / (8 pi), whose 1/pi the Phong family's diffuse
//   term leaves out too);
// - the ambient light reflects off both parts, as a uniform environment
//   reflects off a metal: a metal sphere is not black under ambient light.
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "assets/mesh.hpp"

namespace facet {

struct PhongReading {
    glm::vec3 diffuse;   // the albedo: base * (1 - metallic)
    glm::vec3 specular;  // the highlight's colour: mix(f0, base, metallic)
    float strength;      // the highlight's scale, (n + 8) / 8
    float shininess;     // n
};

// The highlight's scale for exponent n (see above).
inline float normalised_highlight(float shininess) {
    return (shininess + 8.0f) / 8.0f;
}

// `base` the base colour (maps applied), `dielectric_f0` the dielectric's
// reflectance at normal incidence (0.04 at the default ior), and the
// metal and roughness with their maps applied.
inline PhongReading read_metal_rough(const glm::vec3& base, const glm::vec3& dielectric_f0,
                                     float metallic, float roughness) {
    const float n = roughness_exponent(roughness);
    return {base * (1.0f - metallic), glm::mix(dielectric_f0, base, metallic),
            normalised_highlight(n), n};
}

}  // namespace facet
