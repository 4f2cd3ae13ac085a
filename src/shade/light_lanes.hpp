#pragma once
// One light as seen from eight surface points: the unit vectors towards it,
// the light arriving at each, and its shadow map's visibility. The Phong
// models (shade/lighting_batch.cpp) and the physically based one
// (shade/model_pbr.cpp) both read lights through here, so point and spot
// falloff, the range window and shadows have one implementation over lanes
// (shade/light_sample.hpp is the same for one point, for the stylised models).
#include "core/simd_math.hpp"
#include "shade/lighting.hpp"
#include "shade/lighting_batch.hpp"
#include "shade/shadow_map.hpp"

namespace facet {

// What a light brings to each lane: the unit vector towards it, its
// radiance there, and where it arrives at all.
struct IncomingLight {
    simd::vf lx, ly, lz, rr, rg, rb;
    simd::vi usable;
};

[[gnu::always_inline]] inline IncomingLight incoming_light(const ShadeLight& light,
                                                           const SurfaceBatch& p) {
    using simd::splat;
    using simd::vf;
    const vf zero = splat(0.0f);
    vf lx, ly, lz, rr, rg, rb;
    simd::vi usable = simd::splat_i(-1);
    if (light.is_point) {
        vf dx = light.position.x - p.px, dy = light.position.y - p.py, dz = light.position.z - p.pz;
        vf dist2 = dx * dx + dy * dy + dz * dz;
        usable = dist2 > zero;
        vf safe = usable ? dist2 : splat(1.0f);
        vf inv_len = 1.0f / simd::vsqrt(safe);
        lx = dx * inv_len;
        ly = dy * inv_len;
        lz = dz * inv_len;
        vf falloff = 1.0f / safe;  // inverse-square
        if (light.inv_range > 0.0f) falloff *= range_window(dist2, light.inv_range);
        if (light.is_spot)
            falloff *= spot_cone(
                lx * light.direction.x + ly * light.direction.y + lz * light.direction.z, light);
        usable &= falloff > zero;
        rr = light.radiance.x * falloff;
        rg = light.radiance.y * falloff;
        rb = light.radiance.z * falloff;
    } else {
        lx = splat(light.direction.x);
        ly = splat(light.direction.y);
        lz = splat(light.direction.z);
        rr = splat(light.radiance.x);
        rg = splat(light.radiance.y);
        rb = splat(light.radiance.z);
    }
    return {lx, ly, lz, rr, rg, rb, usable};
}

// Darkens the light's radiance by its shadow map at the lanes set in
// `where` that receive shadows, and only there: a shadow map read is the
// costly part.
[[gnu::always_inline]] inline void apply_shadow(const ShadowMap& shadow, const SurfaceBatch& p,
                                                simd::vf nx, simd::vf ny, simd::vf nz,
                                                simd::vi where, IncomingLight& in) {
    const unsigned lanes = simd::movemask(where & (p.receives_shadow > 0.0f));
    const simd::vf visible = shadow_visibility(shadow, {p.px, p.py, p.pz, nx, ny, nz}, lanes);
    in.rr *= visible;
    in.rg *= visible;
    in.rb *= visible;
}

}  // namespace facet
