#pragma once
// Depth view: linear view depth as grey, white at the near end of the range
// and black at the far end, linear in the stored (sRGB) value.
#include <algorithm>

#include "core/color.hpp"
#include "shade/shading_models.hpp"

namespace facet {

inline glm::vec3 shade_depth_view(const SurfaceLanes& in, int lane, glm::vec2 range) {
    const float t = (range.y - in.depth[lane]) / (range.y - range.x);
    return glm::vec3(srgb_to_linear(std::clamp(t, 0.0f, 1.0f)));
}

}  // namespace facet
