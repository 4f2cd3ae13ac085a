#pragma once
// One light as seen from one surface point: the unit vector towards it and
// the light arriving there. The stylised models (palette, Gooch, toon) take
// a list of these, so they need not know light kinds or falloff; the
// numbers match shade/lighting_batch.cpp (inverse-square point and spot
// lights, range window, spot cone).
#include <cmath>

#include <glm/vec3.hpp>

#include "shade/lighting.hpp"

namespace facet {

struct LightSample {
    glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // unit
    glm::vec3 radiance{0.0f};              // colour * intensity arriving at the point
};

// Ambient lights have no direction and give no sample (radiance 0); their
// sum is ambient_light(lights) (shade/lighting.hpp). Shadows are not
// included: multiply by light_visibility (shade/shadow_map.hpp).
inline LightSample sample_light(const ShadeLight& light, const glm::vec3& position) {
    if (light.is_ambient) return {};
    if (!light.is_point) return {light.direction, light.radiance};
    const glm::vec3 d = light.position - position;
    const float dist2 = d.x * d.x + d.y * d.y + d.z * d.z;
    if (!(dist2 > 0.0f)) return {};  // at the light itself: no direction, no light
    const float inv_len = 1.0f / std::sqrt(dist2);
    const glm::vec3 l = d * inv_len;
    float falloff = 1.0f / dist2;  // inverse-square
    if (light.inv_range > 0.0f) falloff *= range_window(dist2, light.inv_range);
    if (light.is_spot)
        falloff *= spot_cone(
            l.x * light.direction.x + l.y * light.direction.y + l.z * light.direction.z, light);
    return {l, light.radiance * falloff};
}

// Unit vector, or `fallback` for a zero vector (as lighting_batch turns a
// zero normal into +Y).
inline glm::vec3 normalise_or(const glm::vec3& v, const glm::vec3& fallback) {
    const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return len > 0.0f ? v * (1.0f / len) : fallback;
}

inline float dot3(const glm::vec3& a, const glm::vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

}  // namespace facet
