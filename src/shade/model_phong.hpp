#pragma once
// Per-pixel lighting: Phong 1975 (highlight from the reflected light
// vector), Blinn 1977 (from the half vector), and flat shading, which is
// Blinn-Phong with the face normal. Eight points at once through
// shade/lighting_batch.hpp; the texture scales the diffuse part, the
// specular colour (white, or a metal-rough material's) the highlight.
#include "shade/shading_models.hpp"

namespace facet {

inline void shade_phong(const SurfaceLanes& in, const ShadingContext& context, Highlight highlight,
                        ShadedLanes& out) {
    const LightingBatch l = light_surface_batch(in.surface, context.eye, context.lights, highlight);
    out.color[0] = in.albedo[0] * l.dr + in.specular_color[0] * l.sr;
    out.color[1] = in.albedo[1] * l.dg + in.specular_color[1] * l.sg;
    out.color[2] = in.albedo[2] * l.db + in.specular_color[2] * l.sb;
}

}  // namespace facet
