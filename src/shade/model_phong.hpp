#pragma once
// Per-pixel lighting: Phong 1975 (highlight from the reflected light
// vector), Blinn 1977 (from the half vector), and flat shading, which is
// Blinn-Phong with the face normal. Eight points at once through
// shade/lighting_batch.hpp; the texture scales the diffuse part.
#include "shade/shading_models.hpp"

namespace facet {

inline void shade_phong(const SurfaceLanes& in, const ShadingContext& context, Highlight highlight,
                        ShadedLanes& out) {
    const LightingBatch l = light_surface_batch(in.surface, context.eye, context.lights, highlight);
    for (int i = 0; i < in.count; ++i) {
        const glm::vec3& a = in.albedo[i];
        out.color[i] =
            glm::vec3(a.x * l.dr[i] + l.sr[i], a.y * l.dg[i] + l.sg[i], a.z * l.db[i] + l.sb[i]);
    }
}

}  // namespace facet
