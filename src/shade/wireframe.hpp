#pragma once
// Wireframe lines drawn while shading a triangle's own pixels, after
// Bærentzen, Munk-Lund, Gjøl & Larsen 2006, "Single-pass Wireframe
// Rendering": each pixel knows its distance in pixels to the three edges of
// the triangle it shows, and is covered where the nearest edge is within
// half the line width. No second pass, no depth offset, no z-fighting
// (seed 001's wireframe display mode; seed 004 draws Bresenham lines,
// which these anti-aliased lines replace: docs/references.md).
//
// The coverage ramp is clamp(w/2 + 0.5 − d, 0, 1), a pixel-wide box
// filter, the same as post/outlines.hpp, so lines of both agree in width.
// A line on an edge shared by two triangles gets half its width from each
// side; on a silhouette only the inner half is drawn (the outline pass can
// add the outer half).
//
// Per pixel, with the barycentrics and their screen derivatives that the
// shading stage already computes for texture LOD:
//   glm::vec3 d = edge_distances(b, db_dx, db_dy);
//   float a = wire_coverage(d, style.width, style.edges);
//   colour = mix(colour, style.color, a)
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace facet {

struct WireframeStyle {
    float width = 1.0f;      // pixels, across the whole line
    glm::vec3 color{0.0f};   // linear RGB
    unsigned edges = 0b111;  // bit i draws the edge opposite vertex i (hide quad diagonals)
};

// Distance in pixels from p to each edge line of the screen triangle
// (a, b, c): component i for the edge opposite vertex i. Exact.
inline glm::vec3 edge_distances(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    auto to_line = [p](glm::vec2 from, glm::vec2 to) {
        const glm::vec2 e = to - from, q = p - from;
        const float len = std::sqrt(e.x * e.x + e.y * e.y);
        if (!(len > 0.0f)) return std::numeric_limits<float>::infinity();
        return std::fabs(e.x * q.y - e.y * q.x) / len;
    };
    return {to_line(b, c), to_line(c, a), to_line(a, b)};
}

// The same from barycentrics b and their screen-space derivatives: b_i is
// zero on edge i and changes by |∇b_i| per pixel, so d_i = b_i / |∇b_i|.
// Exact for screen-linear barycentrics; for perspective-correct ones a
// first-order estimate, accurate near the edge, which is where it matters.
inline glm::vec3 edge_distances(glm::vec3 bary, glm::vec3 db_dx, glm::vec3 db_dy) {
    glm::vec3 d;
    for (int i = 0; i < 3; ++i) {
        const float grad = std::sqrt(db_dx[i] * db_dx[i] + db_dy[i] * db_dy[i]);
        d[i] =
            grad > 0.0f ? std::max(bary[i], 0.0f) / grad : std::numeric_limits<float>::infinity();
    }
    return d;
}

// Line coverage in [0, 1] for a line `width` pixels wide centred on the
// nearest enabled edge.
inline float wire_coverage(glm::vec3 distances, float width, unsigned edges = 0b111) {
    float nearest = std::numeric_limits<float>::infinity();
    for (int i = 0; i < 3; ++i)
        if (edges & (1u << i)) nearest = std::min(nearest, distances[i]);
    return std::clamp(0.5f * width + 0.5f - nearest, 0.0f, 1.0f);
}

}  // namespace facet
