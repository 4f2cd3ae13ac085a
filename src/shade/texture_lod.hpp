#pragma once
// Texture coordinates at a pixel and their level of detail, from a
// triangle's three coordinates and the pixel's surface sample: the one
// place the level of detail is computed (material textures and hatching
// strokes alike).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "raster/surface_sample.hpp"

namespace facet {

struct TextureLookup {
    glm::vec2 uv;  // interpolated, perspective-correct
    float lod;     // log2 of texels per pixel step (0 when magnified), for mip selection
};

// uv0..uv2 are the triangle's coordinates, already in the texture's tiling
// units; `texels` the texture's size in texels per unit. The footprint is
// the longer of the two screen-axis steps (Williams 1983, "Pyramidal
// Parametrics"), from the barycentric derivatives.
inline TextureLookup texture_lookup(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2,
                                    const SurfaceSample& s, glm::vec2 texels) {
    const glm::vec2 e1 = uv1 - uv0, e2 = uv2 - uv0;
    const glm::vec2 ddx = (e1 * s.ddx.y + e2 * s.ddx.z) * texels;
    const glm::vec2 ddy = (e1 * s.ddy.y + e2 * s.ddy.z) * texels;
    const float footprint = std::max(glm::length(ddx), glm::length(ddy));
    return {uv0 + e1 * s.bary.y + e2 * s.bary.z, footprint > 1.0f ? std::log2(footprint) : 0.0f};
}

}  // namespace facet
