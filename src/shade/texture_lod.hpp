#pragma once
// Texture coordinates at a pixel and its footprint, from a triangle's three
// coordinates and the pixel's surface sample: the one place the footprint
// of a material's texture is computed.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "assets/texture.hpp"
#include "core/simd_math.hpp"
#include "raster/surface_sample.hpp"

namespace facet {

// uv0..uv2 are the triangle's coordinates, already in the texture's tiling
// units; `texels` the texture's size in texels per unit. The pixel's
// footprint is its two screen-axis steps (Williams 1983, "Pyramidal
// Parametrics"), from the barycentric derivatives: the texture filters by
// the longer, and reads more of it along its length when anisotropic
// (Texture::sample).
inline TextureFootprint texture_lookup(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2,
                                       const SurfaceSample& s, glm::vec2 texels) {
    const glm::vec2 e1 = uv1 - uv0, e2 = uv2 - uv0;
    const glm::vec2 step_x = e1 * s.ddx.y + e2 * s.ddx.z;
    const glm::vec2 step_y = e1 * s.ddy.y + e2 * s.ddy.z;
    const float across_x = glm::length(step_x * texels);
    const float across_y = glm::length(step_y * texels);
    const bool y_longer = across_x < across_y;  // std::max's choice
    return {uv0 + e1 * s.bary.y + e2 * s.bary.z, y_longer ? step_y : step_x,
            y_longer ? across_y : across_x, y_longer ? across_x : across_y};
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
    simd::vf u, v;
    simd::vf axis_u, axis_v;  // TextureFootprint::major_axis
    simd::vf major, minor;
    TextureFootprint at(int lane) const {
        return {{u[lane], v[lane]}, {axis_u[lane], axis_v[lane]}, major[lane], minor[lane]};
    }
};

inline TextureLookupLanes texture_lookups(const UvLanes& c, const FootprintLanes& s,
                                          glm::vec2 texels) {
    using simd::vf;
    const vf e1u = c.u[1] - c.u[0], e1v = c.v[1] - c.v[0];
    const vf e2u = c.u[2] - c.u[0], e2v = c.v[2] - c.v[0];
    const vf step_xu = e1u * s.ddx1 + e2u * s.ddx2, step_xv = e1v * s.ddx1 + e2v * s.ddx2;
    const vf step_yu = e1u * s.ddy1 + e2u * s.ddy2, step_yv = e1v * s.ddy1 + e2v * s.ddy2;
    const vf ddxu = step_xu * texels.x, ddxv = step_xv * texels.y;
    const vf ddyu = step_yu * texels.x, ddyv = step_yv * texels.y;
    const vf across_x = simd::vsqrt(ddxu * ddxu + ddxv * ddxv);
    const vf across_y = simd::vsqrt(ddyu * ddyu + ddyv * ddyv);
    const simd::vi y_longer = across_x < across_y;  // std::max's choice
    TextureLookupLanes out;
    out.u = (c.u[0] + e1u * s.b1) + e2u * s.b2;
    out.v = (c.v[0] + e1v * s.b1) + e2v * s.b2;
    out.axis_u = y_longer ? step_yu : step_xu;
    out.axis_v = y_longer ? step_yv : step_xv;
    out.major = y_longer ? across_y : across_x;
    out.minor = y_longer ? across_x : across_y;
    return out;
}

}  // namespace facet
