#pragma once
// What the visibility buffer says about a point of the image, reconstructed
// from the triangle's setup record: perspective-correct barycentrics of the
// source triangle, their screen derivatives, and the depth along the viewing
// axis. reconstruct_surfaces is the one place this is computed, eight points
// at a time; shading, outlines and passes read it.
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"
#include "raster/setup_bins.hpp"

namespace facet {

// The setup planes of eight points (lane i from the triangle lane i shows).
struct SetupLanes {
    simd::vf x0, y0;
    simd::vf inv_w[3], b1_w[3], b2_w[3];
};

[[gnu::always_inline]] inline SetupLanes splat_setup(const ShadeSetup& s) {
    SetupLanes l;
    l.x0 = simd::splat(s.x0);
    l.y0 = simd::splat(s.y0);
    for (int k = 0; k < 3; ++k) {
        l.inv_w[k] = simd::splat(s.inv_w[k]);
        l.b1_w[k] = simd::splat(s.b1_w[k]);
        l.b2_w[k] = simd::splat(s.b2_w[k]);
    }
    return l;
}

// The lanes where `mask` is set take `s`'s planes.
[[gnu::always_inline]] inline void select_setup(SetupLanes& l, simd::vi mask, const ShadeSetup& s) {
    l.x0 = mask ? simd::splat(s.x0) : l.x0;
    l.y0 = mask ? simd::splat(s.y0) : l.y0;
    for (int k = 0; k < 3; ++k) {
        l.inv_w[k] = mask ? simd::splat(s.inv_w[k]) : l.inv_w[k];
        l.b1_w[k] = mask ? simd::splat(s.b1_w[k]) : l.b1_w[k];
        l.b2_w[k] = mask ? simd::splat(s.b2_w[k]) : l.b2_w[k];
    }
}

struct SurfaceSamples {
    simd::vf w;               // clip-space w: the distance along the viewing axis
    simd::vf bary[3];         // weights of the source triangle's vertices 0, 1, 2
    simd::vf ddx[3], ddy[3];  // their derivatives per unit step in x and y
};

// At (x, y) in the rasterizer's pixels. b/w and 1/w are affine in screen
// space, b is not (Heckbert & Moreton 1991, "Interpolation for Polygon
// Texture Mapping and Shading"), so b = (b/w) / (1/w); its derivatives
// follow by the quotient rule. Each lane does the same IEEE operations as
// every other, so a point gives the same bits in any lane.
[[gnu::always_inline]] inline SurfaceSamples reconstruct_surfaces(const SetupLanes& s, simd::vf x,
                                                                  simd::vf y) {
    const simd::vf fx = x - s.x0, fy = y - s.y0;
    const simd::vf inv_w = s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy;
    const simd::vf w = 1.0f / inv_w;
    const simd::vf b1 = (s.b1_w[0] + s.b1_w[1] * fx + s.b1_w[2] * fy) * w;
    const simd::vf b2 = (s.b2_w[0] + s.b2_w[1] * fx + s.b2_w[2] * fy) * w;
    const simd::vf db1dx = (s.b1_w[1] - b1 * s.inv_w[1]) * w;
    const simd::vf db1dy = (s.b1_w[2] - b1 * s.inv_w[2]) * w;
    const simd::vf db2dx = (s.b2_w[1] - b2 * s.inv_w[1]) * w;
    const simd::vf db2dy = (s.b2_w[2] - b2 * s.inv_w[2]) * w;
    SurfaceSamples out;
    out.w = w;
    out.bary[0] = 1.0f - b1 - b2;
    out.bary[1] = b1;
    out.bary[2] = b2;
    out.ddx[0] = -db1dx - db2dx;
    out.ddx[1] = db1dx;
    out.ddx[2] = db2dx;
    out.ddy[0] = -db1dy - db2dy;
    out.ddy[1] = db1dy;
    out.ddy[2] = db2dy;
    return out;
}

// One point, as the scalar code paths (texture lookups) take it.
struct SurfaceSample {
    uint32_t triangle;  // source triangle (World's triangle order)
    bool back_facing;   // the camera sees its back
    float w;
    glm::vec3 bary;
    glm::vec3 ddx, ddy;
};

inline SurfaceSample surface_lane(const SurfaceSamples& s, int lane, const ShadeSetup& setup) {
    SurfaceSample out;
    out.triangle = setup.source_triangle;
    out.back_facing = setup.back_facing != 0;
    out.w = s.w[lane];
    out.bary = {s.bary[0][lane], s.bary[1][lane], s.bary[2][lane]};
    out.ddx = {s.ddx[0][lane], s.ddx[1][lane], s.ddx[2][lane]};
    out.ddy = {s.ddy[0][lane], s.ddy[1][lane], s.ddy[2][lane]};
    return out;
}

// At the centre of pixel (x, y), through reconstruct_surfaces.
inline SurfaceSample reconstruct_surface(const ShadeSetup& s, int x, int y) {
    const SurfaceSamples all =
        reconstruct_surfaces(splat_setup(s), simd::splat(static_cast<float>(x) + 0.5f),
                             simd::splat(static_cast<float>(y) + 0.5f));
    return surface_lane(all, 0, s);
}

}  // namespace facet
