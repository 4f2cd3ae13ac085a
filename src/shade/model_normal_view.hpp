#pragma once
// Normal view: the unit normal n (world space) shown as the bytes
// 255 * (n * 0.5 + 0.5), the usual normal-map colours.
#include "core/color.hpp"
#include "shade/shading_models.hpp"

namespace facet {

inline void shade_normal_view(const SurfaceLanes& in, ShadedLanes& out) {
    for (int i = 0; i < in.count; ++i) {
        const glm::vec3 normal(in.surface.nx[i], in.surface.ny[i], in.surface.nz[i]);
        const float len = glm::length(normal);
        const glm::vec3 n = (len > 0 ? normal / len : glm::vec3(0, 1, 0)) * 0.5f + 0.5f;
        // Shown as the stored bytes, so undo the sRGB encoding to come.
        out.set(i, {srgb_to_linear(n.x), srgb_to_linear(n.y), srgb_to_linear(n.z)});
    }
}

}  // namespace facet
