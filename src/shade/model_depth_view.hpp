#pragma once
// Depth view: linear view depth as grey, white at the near end of the range
// and black at the far end, linear in the stored (sRGB) value.
#include <algorithm>

#include "core/color.hpp"
#include "shade/shading_models.hpp"

namespace facet {

inline void shade_depth_view(const SurfaceLanes& in, glm::vec2 range, ShadedLanes& out) {
    for (int i = 0; i < in.count; ++i) {
        const float t = (range.y - in.depth[i]) / (range.y - range.x);
        out.set(i, glm::vec3(srgb_to_linear(std::clamp(t, 0.0f, 1.0f))));
    }
}

}  // namespace facet
