#pragma once
// The lighting of lighting.hpp for eight surface points at once (the
// shading stage's hot loop). Results agree with light_surface to about
// 1e-6 and are identical on every CPU.
#include <span>

#include "shade/lighting.hpp"
#include "shade/simd_math.hpp"

namespace facet {

struct SurfaceBatch {
    simd::vf px, py, pz;  // position
    simd::vf nx, ny, nz;  // normal on the viewer's side, any length (normalised here)
    simd::vf ambient, diffuse, specular, shininess;
};

struct LightingBatch {
    simd::vf dr, dg, db;  // diffuse light (multiplies albedo)
    simd::vf sr, sg, sb;  // specular light (added)
};

LightingBatch light_surface_batch(const SurfaceBatch& s, const glm::vec3& eye,
                                  std::span<const ShadeLight> lights, Highlight highlight);

}  // namespace facet
