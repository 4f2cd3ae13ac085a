#pragma once
// Unlit: the object's colour (texture included) as it is.
#include "shade/shading_models.hpp"

namespace facet {

inline void shade_unlit(const SurfaceLanes& in, ShadedLanes& out) {
    for (int c = 0; c < 3; ++c) out.color[c] = in.albedo[c];
}

}  // namespace facet
