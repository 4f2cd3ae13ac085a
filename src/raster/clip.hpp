#pragma once
// Polygon clipping in homogeneous clip space (Sutherland & Hodgman 1974;
// Blinn & Newell 1978), against the near and far planes and the guard band.
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

struct ClipVertex {
    glm::vec4 position;  // clip space
    glm::vec3 bary;      // weights of the source triangle's vertices
};

// A triangle clipped against six planes has at most 3 + 6 vertices.
constexpr int kMaxClippedVertices = 9;

// Bit per plane that a clip-space point is outside of, in the order near,
// far, left, right, bottom, top. `guard` is the guard band half-size in NDC
// units for x and y. Reversed-Z clip space: near is z = w, far z = 0.
inline uint32_t clip_outcode(const glm::vec4& p, float guard_x, float guard_y) {
    return static_cast<uint32_t>(p.w - p.z < 0) | static_cast<uint32_t>(p.z < 0) << 1 |
           static_cast<uint32_t>(guard_x * p.w + p.x < 0) << 2 |
           static_cast<uint32_t>(guard_x * p.w - p.x < 0) << 3 |
           static_cast<uint32_t>(guard_y * p.w + p.y < 0) << 4 |
           static_cast<uint32_t>(guard_y * p.w - p.y < 0) << 5;
}

// Clips the segment a-b to the near plane in place, interpolating from the
// end in front of it as clip_triangle does. False when nothing is left, or
// an end is not in front of the eye (w <= 0).
bool clip_segment_to_near(glm::vec4& a, glm::vec4& b);

// Clip space to screen pixels (x right, y down, the image's top-left corner
// at 0), as the primitive stage maps vertices.
inline glm::vec2 clip_to_screen(const glm::vec4& v, float half_width, float half_height) {
    const float inv_w = 1.0f / v.w;
    return {(v.x * inv_w + 1.0f) * half_width, (1.0f - v.y * inv_w) * half_height};
}

// Clips the triangle to the inside of every plane in `planes` (outcode
// bits). Returns the vertex count of the resulting convex polygon (0 if
// nothing is left), written to `out`.
int clip_triangle(const ClipVertex in[3], uint32_t planes, float guard_x, float guard_y,
                  ClipVertex out[kMaxClippedVertices]);

}  // namespace facet
