#pragma once
// Types shared by the lighting models (shade/lighting_batch.hpp): Phong
// (Phong 1975) and Blinn-Phong (Blinn 1977) reflection, evaluated per pixel
// (Phong shading) or per vertex (Gouraud 1971). Colours are linear RGB.
#include <algorithm>
#include <span>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"
#include "shade/lanes.hpp"

namespace facet {

struct ShadowMap;  // shade/shadow_map.hpp

// One light as the shading stages see it. Directional, point and spot
// lights shine from a direction; ambient lights light every surface alike.
// The first four members keep their order, so `{is_point, direction,
// position, radiance}` still makes a directional or point light.
struct ShadeLight {
    bool is_point = false;      // has a position and falls off with distance: point and spot lights
    glm::vec3 direction{0.0f};  // unit, towards the light: directional; spot: its axis reversed
    glm::vec3 position{0.0f};   // point, spot
    glm::vec3 radiance{0.0f};   // colour * intensity
    bool is_ambient = false;    // adds radiance * ka * albedo everywhere; direction unused
    bool is_spot = false;       // a point light limited to a cone round -direction
    // Spot cone: the smoothstep of (cos angle * spot_scale + spot_offset),
    // which is 0 at the outer half-angle and 1 at the inner one.
    float spot_scale = 0.0f, spot_offset = 1.0f;
    float inv_range = 0.0f;             // point, spot: 1 / range; 0 for no range
    const ShadowMap* shadow = nullptr;  // the light's shadow map this frame, if it casts shadows
};

// Light arriving at a point, split so that a texture can scale the diffuse
// part only: colour = albedo * diffuse + specular.
struct LightingResult {
    glm::vec3 diffuse;
    glm::vec3 specular;
};

enum class Highlight { phong, blinn };

// The falloff formulas, written once for one value (float) and for eight
// (simd::vf), so per-pixel, per-vertex and stylised shading agree. Always
// inlined, like simd_math.hpp's helpers, for the AVX2 clones that call them.
// The range window of glTF's KHR_lights_punctual (after Karis 2013, "Real
// Shading in Unreal Engine 4"): clamp(1 - (d / range)^4, 0, 1)^2, which
// multiplies the inverse-square falloff and reaches zero, smoothly, at the
// range. `dist2` is d^2.
template <typename T>
[[gnu::always_inline]] inline T range_window(T dist2, float inv_range) {
    const T x = dist2 * (inv_range * inv_range);  // (d / range)^2
    const T w = lanes::clamp01(1.0f - x * x);
    return w * w;
}

// The spot cone's smooth edge: smoothstep in the cosine of the angle from
// the axis, 0 outside the outer cone and 1 inside the inner one.
template <typename T>
[[gnu::always_inline]] inline T spot_cone(T cos_angle, const ShadeLight& light) {
    const T t = lanes::clamp01(cos_angle * light.spot_scale + light.spot_offset);
    return t * t * (3.0f - 2.0f * t);
}

// spot_scale and spot_offset for cone half-angles in degrees, inner <= outer.
// An inner angle equal to the outer one gives a hard edge (a 0.001 band in
// cos, as glTF's reference formula does).
void set_spot_cone(ShadeLight& light, float inner_degrees, float outer_degrees);

// The ambient light: the sum of the ambient lights, or white of intensity 1
// when there are none (so a material's ambient coefficient alone sets its
// ambient term, as in the seed-001 Phong model).
inline glm::vec3 ambient_light(std::span<const ShadeLight> lights) {
    glm::vec3 sum(0.0f);
    bool any = false;
    for (const ShadeLight& l : lights)
        if (l.is_ambient) {
            sum += l.radiance;
            any = true;
        }
    return any ? sum : glm::vec3(1.0f);
}

}  // namespace facet
