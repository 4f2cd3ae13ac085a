#pragma once
// Polygon clipping in homogeneous clip space (Sutherland & Hodgman 1974;
// Blinn & Newell 1978), against the near and far planes and the guard band.
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

struct ClipVertex {
    glm::vec4 position;  // clip space
    glm::vec3 bary;      // weights of the source triangle's vertices
};

// A triangle clipped against six planes has at most 3 + 6 vertices.
constexpr int kMaxClippedVertices = 9;

// Bit per plane that a clip-space point is outside of. `guard` is the guard
// band half-size in NDC units for x and y.
uint32_t clip_outcode(const glm::vec4& p, float guard_x, float guard_y);

// Clips the triangle to the inside of every plane in `planes` (outcode
// bits). Returns the vertex count of the resulting convex polygon (0 if
// nothing is left), written to `out`.
int clip_triangle(const ClipVertex in[3], uint32_t planes, float guard_x, float guard_y,
                  ClipVertex out[kMaxClippedVertices]);

}  // namespace facet
