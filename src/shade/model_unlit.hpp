#pragma once
// Unlit: the object's colour (texture included) as it is.
#include "shade/shading_models.hpp"

namespace facet {

inline glm::vec3 shade_unlit(const SurfaceLanes& in, int lane) {
    return in.albedo[lane];
}

}  // namespace facet
