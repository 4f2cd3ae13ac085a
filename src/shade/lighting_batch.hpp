#pragma once
// Lighting for eight surface points at once: the per-pixel shading stage
// and Gouraud's per-vertex lighting both go through here, so there is one
// implementation of the formulas. Results are identical on every CPU.
#include <span>

#include "core/simd_math.hpp"
#include "shade/lighting.hpp"

namespace facet {

struct SurfaceBatch {
    simd::vf px, py, pz;  // position
    simd::vf nx, ny, nz;  // normal on the viewer's side, any length (normalised here)
    simd::vf ambient, diffuse, specular, shininess;
    // 1 where shadows darken the point, 0 where its object does not receive them.
    simd::vf receives_shadow = simd::splat(1.0f);
    // The ambient term of the highlight: the ambient light a metal-rough
    // material reflects in its specular colour (shade/metal_rough_phong.hpp).
    simd::vf ambient_specular = simd::splat(0.0f);
};

struct LightingBatch {
    simd::vf dr, dg, db;  // diffuse light (multiplies albedo)
    simd::vf sr, sg, sb;  // specular light (added)
};

// Fills lanes [count, 8) with copies of lane 0, so a partly filled batch
// computes harmless values in its unused lanes.
void pad_batch(SurfaceBatch& s, int count);

// Ambient lights add ambient * their radiance (white 1 without any, see
// ambient_light) to the diffuse light, and ambient_specular * their
// radiance to the specular light; every other light adds its diffuse and highlight, each
// times the light's shadow visibility at that lane (shade/shadow_map.hpp).
LightingBatch light_surface_batch(const SurfaceBatch& s, const glm::vec3& eye,
                                  std::span<const ShadeLight> lights, Highlight highlight);

}  // namespace facet
