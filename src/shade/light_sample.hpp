#pragma once
// One light as seen from a surface point, written once for one point
// (float) and for eight (simd::vf, shade/lanes.hpp): the unit vector
// towards it and the light arriving there (inverse-square point and spot
// lights, glTF's range window, the spot cone), and its shadow map's
// visibility. The Phong models (shade/lighting_batch.cpp), the physically
// based one (shade/model_pbr.cpp) and the stylised ones (through
// sample_light) all read lights through here.
#include <cmath>

#include <glm/vec3.hpp>

#include "shade/lanes.hpp"
#include "shade/lighting.hpp"
#include "shade/shadow_map.hpp"

namespace facet {

// What a light brings to a point: the unit vector towards it, its radiance
// there, and whether it arrives at all. Where it does not (the point is at
// the light, outside its range or cone), the radiance is 0.
template <typename T>
struct IncomingLight {
    lanes::Vec3<T> to_light;
    lanes::Vec3<T> radiance;
    lanes::Mask<T> usable;
};

template <typename T>
[[gnu::always_inline]] inline IncomingLight<T> incoming_light(const ShadeLight& light,
                                                              const lanes::Vec3<T>& position) {
    using lanes::select, lanes::splat;
    const T zero = splat<T>(0.0f);
    if (!light.is_point)
        return {
            {splat<T>(light.direction.x), splat<T>(light.direction.y), splat<T>(light.direction.z)},
            {splat<T>(light.radiance.x), splat<T>(light.radiance.y), splat<T>(light.radiance.z)},
            lanes::Mask<T>(lanes::splat_mask<T>(true))};
    const T dx = light.position.x - position[0], dy = light.position.y - position[1],
            dz = light.position.z - position[2];
    const T dist2 = dx * dx + dy * dy + dz * dz;
    const lanes::Mask<T> near = dist2 > zero;  // at the light itself: no direction, no light
    const T safe = select(near, dist2, splat<T>(1.0f));
    const T inv_len = 1.0f / lanes::square_root(safe);
    const lanes::Vec3<T> l = {select(near, dx * inv_len, zero),
                              select(near, dy * inv_len, splat<T>(1.0f)),
                              select(near, dz * inv_len, zero)};
    T falloff = 1.0f / safe;  // inverse-square
    if (light.inv_range > 0.0f) falloff *= range_window(dist2, light.inv_range);
    if (light.is_spot)
        falloff *= spot_cone(
            l[0] * light.direction.x + l[1] * light.direction.y + l[2] * light.direction.z, light);
    const lanes::Mask<T> usable = near & (falloff > zero);
    const T kept = select(near, falloff, zero);
    return {l, {light.radiance.x * kept, light.radiance.y * kept, light.radiance.z * kept}, usable};
}

// Darkens the light's radiance by its shadow map (shade/shadow_map.hpp) where
// `where` is set: one point, or the lanes of eight (a shadow map read is the
// costly part, so only those are read). `normal` is the surface normal on
// the light's side, any length.
inline void apply_shadow(const ShadowMap& shadow, const lanes::Vec3<float>& position,
                         const lanes::Vec3<float>& normal, bool where, IncomingLight<float>& in) {
    if (!where) return;
    const float visible = shadow_visibility(shadow, {position[0], position[1], position[2]},
                                            {normal[0], normal[1], normal[2]});
    for (float& channel : in.radiance) channel *= visible;
}
[[gnu::always_inline]] inline void apply_shadow(const ShadowMap& shadow,
                                                const lanes::Vec3<simd::vf>& position,
                                                const lanes::Vec3<simd::vf>& normal, simd::vi where,
                                                IncomingLight<simd::vf>& in) {
    const simd::vf visible = shadow_visibility(
        shadow, {position[0], position[1], position[2], normal[0], normal[1], normal[2]},
        simd::movemask(where));
    for (simd::vf& channel : in.radiance) channel *= visible;
}

// One light at one point, for the stylised models (palette, Gooch, toon),
// which need not know light kinds or falloff. Ambient lights have no
// direction and give no sample (radiance 0); their sum is
// ambient_light(lights) (shade/lighting.hpp). Shadows are not included:
// multiply by light_visibility (shade/shadow_map.hpp).
struct LightSample {
    glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // unit
    glm::vec3 radiance{0.0f};              // colour * intensity arriving at the point
};

inline LightSample sample_light(const ShadeLight& light, const glm::vec3& position) {
    if (light.is_ambient) return {};
    const IncomingLight<float> in =
        incoming_light<float>(light, {position.x, position.y, position.z});
    return {{in.to_light[0], in.to_light[1], in.to_light[2]},
            {in.radiance[0], in.radiance[1], in.radiance[2]}};
}

// Unit vector, or `fallback` for a zero vector (lanes::normalise_or for one point).
inline glm::vec3 normalise_or(const glm::vec3& v, const glm::vec3& fallback) {
    const lanes::Vec3<float> n =
        lanes::normalise_or<float>({v.x, v.y, v.z}, {fallback.x, fallback.y, fallback.z});
    return {n[0], n[1], n[2]};
}

inline float dot3(const glm::vec3& a, const glm::vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

}  // namespace facet
