#pragma once
// Texture coordinates at a pixel and their level of detail, from a
// triangle's three coordinates and the pixel's surface sample: the one
// place the level of detail is computed (material textures and hatching
// strokes alike).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/simd_math.hpp"
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

// The same for eight lanes, with the same operations in the same order,
// so each lane gets the bits texture_lookup gives it.
struct UvLanes {
    simd::vf u[3], v[3];  // a triangle's three corners' coordinates, per lane
};

struct FootprintLanes {
    simd::vf b1, b2;      // the weights of corners 1 and 2 at the point
    simd::vf ddx1, ddx2;  // their steps per pixel across x
    simd::vf ddy1, ddy2;  // and across y
};

struct TextureLookupLanes {
    simd::vf u, v, lod;
};

inline TextureLookupLanes texture_lookups(const UvLanes& c, const FootprintLanes& s,
                                          glm::vec2 texels) {
    using simd::vf;
    const vf e1u = c.u[1] - c.u[0], e1v = c.v[1] - c.v[0];
    const vf e2u = c.u[2] - c.u[0], e2v = c.v[2] - c.v[0];
    const vf ddxu = (e1u * s.ddx1 + e2u * s.ddx2) * texels.x;
    const vf ddxv = (e1v * s.ddx1 + e2v * s.ddx2) * texels.y;
    const vf ddyu = (e1u * s.ddy1 + e2u * s.ddy2) * texels.x;
    const vf ddyv = (e1v * s.ddy1 + e2v * s.ddy2) * texels.y;
    const vf across_x = simd::vsqrt(ddxu * ddxu + ddxv * ddxv);
    const vf across_y = simd::vsqrt(ddyu * ddyu + ddyv * ddyv);
    const vf footprint = across_x < across_y ? across_y : across_x;  // std::max's choice
    TextureLookupLanes out;
    out.u = (c.u[0] + e1u * s.b1) + e2u * s.b2;
    out.v = (c.v[0] + e1v * s.b1) + e2v * s.b2;
    for (int i = 0; i < simd::kLanes; ++i)
        out.lod[i] = footprint[i] > 1.0f ? std::log2(footprint[i]) : 0.0f;
    return out;
}

}  // namespace facet
