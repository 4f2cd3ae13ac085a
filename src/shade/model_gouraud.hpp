#pragma once
// Gouraud 1971: Blinn-Phong evaluated at the vertices (render/vertex_stage)
// and interpolated across the triangle; the texture scales the diffuse part.
#include "shade/shading_models.hpp"

namespace facet {

inline glm::vec3 shade_gouraud(const SurfaceLanes& in, int lane) {
    const LightingResult& l = in.vertex_light[lane];
    return in.albedo[lane] * l.diffuse + l.specular;
}

}  // namespace facet
