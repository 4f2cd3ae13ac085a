#pragma once
// What the visibility buffer says about one pixel, reconstructed from the
// triangle's setup record: perspective-correct barycentrics of the source
// triangle, their screen derivatives, and the depth along the viewing axis.
// The one place this is computed; shading, outlines and passes read it.
#include <cstdint>

#include <glm/vec3.hpp>

#include "raster/setup_bins.hpp"

namespace facet {

struct SurfaceSample {
    uint32_t triangle;  // source triangle (World's triangle order)
    bool back_facing;   // the camera sees its back
    float w;            // clip-space w: the distance along the viewing axis
    glm::vec3 bary;     // weights of the source triangle's vertices 0, 1, 2
    // d(bary)/dx and d(bary)/dy per pixel: texture and stroke levels of
    // detail, and wire widths.
    glm::vec3 ddx, ddy;
};

// At the centre of pixel (x, y). b/w and 1/w are affine in screen space, b
// is not (Heckbert & Moreton 1991, "Interpolation for Polygon Texture
// Mapping and Shading"), so b = (b/w) / (1/w); its derivatives follow by
// the quotient rule.
inline SurfaceSample reconstruct_surface(const ShadeSetup& s, int x, int y) {
    const float fx = (static_cast<float>(x) + 0.5f) - s.x0;
    const float fy = (static_cast<float>(y) + 0.5f) - s.y0;
    const float inv_w = s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy;
    const float w = 1.0f / inv_w;
    const float b1 = (s.b1_w[0] + s.b1_w[1] * fx + s.b1_w[2] * fy) * w;
    const float b2 = (s.b2_w[0] + s.b2_w[1] * fx + s.b2_w[2] * fy) * w;
    const float db1dx = (s.b1_w[1] - b1 * s.inv_w[1]) * w;
    const float db1dy = (s.b1_w[2] - b1 * s.inv_w[2]) * w;
    const float db2dx = (s.b2_w[1] - b2 * s.inv_w[1]) * w;
    const float db2dy = (s.b2_w[2] - b2 * s.inv_w[2]) * w;
    SurfaceSample out;
    out.triangle = s.source_triangle;
    out.back_facing = s.back_facing != 0;
    out.w = w;
    out.bary = glm::vec3(1.0f - b1 - b2, b1, b2);
    out.ddx = glm::vec3(-db1dx - db2dx, db1dx, db2dx);
    out.ddy = glm::vec3(-db1dy - db2dy, db1dy, db2dy);
    return out;
}

}  // namespace facet
