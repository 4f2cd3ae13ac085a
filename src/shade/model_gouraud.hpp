#pragma once
// Gouraud 1971: Blinn-Phong evaluated at the vertices (render/vertex_stage)
// and interpolated across the triangle; the texture scales the diffuse part,
// the specular colour (white, or a metal-rough material's) the highlight.
#include "shade/shading_models.hpp"

namespace facet {

inline void shade_gouraud(const SurfaceLanes& in, ShadedLanes& out) {
    for (int c = 0; c < 3; ++c)
        out.color[c] =
            in.albedo[c] * in.vertex_diffuse[c] + in.specular_color[c] * in.vertex_specular[c];
}

}  // namespace facet
