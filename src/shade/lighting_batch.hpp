#pragma once
// Lighting for eight surface points at once: the per-pixel shading stage
// and Gouraud's per-vertex lighting both go through here, so there is one
// implementation of the formulas. Results are identical on every CPU.
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

// Fills lanes [count, 8) with copies of lane 0, so a partly filled batch
// computes harmless values in its unused lanes.
void pad_batch(SurfaceBatch& s, int count);

LightingBatch light_surface_batch(const SurfaceBatch& s, const glm::vec3& eye,
                                  std::span<const ShadeLight> lights, Highlight highlight);

}  // namespace facet
