// The flag scene's primitives (docs/references.md, seed 004 §1.2): the flagpole, a
// cylinder with a hemispherical tip whose radius is the pole's diameter (as
// the seed says), on a flat shoulder, and the platform, a
// square slab with a round hole through its centre for the pole. Both are
// closed, outward-facing meshes; the types are registered in primitives.cpp.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "shapes/primitive_builder.hpp"

namespace facet::detail {
namespace {

// The angle of column s of n round the Y axis, computed exactly as the other
// round primitives do (primitives.cpp), so a pole and a hole of the same
// radius and segments have the same corners and fit without a gap.
float column_angle(int s, int segments) {
    return 2 * kPi * static_cast<float>(s) / static_cast<float>(segments);
}

// One row of a solid of revolution round Y: its radius and height, the
// normal's outward and upward parts, and the texture's v.
struct ProfilePoint {
    float radius, y, normal_out, normal_up, v;
};

// Revolves `profile` (top to bottom) round the Y axis. Each row has
// segments + 1 vertices so the UV seam has its own column; a row of radius 0
// is a pole, closed with triangles. The winding is the sphere's in
// primitives.cpp (outward).
void add_revolved(Builder& b, const std::vector<ProfilePoint>& profile, int segments) {
    const uint32_t first = static_cast<uint32_t>(b.part.positions.size());
    for (const ProfilePoint& p : profile)
        for (int s = 0; s <= segments; ++s) {
            const float phi = column_angle(s, segments);
            const float x = std::sin(phi), z = std::cos(phi);
            b.vertex({x * p.radius, p.y, z * p.radius},
                     {x * p.normal_out, p.normal_up, z * p.normal_out},
                     {static_cast<float>(s) / static_cast<float>(segments), p.v});
        }
    const auto at = [&](size_t r, int s) {
        return first + static_cast<uint32_t>(r * static_cast<size_t>(segments + 1) + s);
    };
    for (size_t r = 0; r + 1 < profile.size(); ++r)
        for (int s = 0; s < segments; ++s) {
            if (profile[r].radius == 0)
                b.triangle(at(r, s), at(r + 1, s), at(r + 1, s + 1));
            else if (profile[r + 1].radius == 0)
                b.triangle(at(r, s), at(r + 1, s), at(r, s + 1));
            else
                b.quad(at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
        }
}

// A flat disc facing down at height y (the pole's foot).
void add_bottom_cap(Builder& b, float radius, float y, int segments) {
    const glm::vec3 n(0, -1, 0);
    const uint32_t centre = b.vertex({0, y, 0}, n, {0.5f, 0.5f});
    const uint32_t ring = static_cast<uint32_t>(b.part.positions.size());
    for (int s = 0; s <= segments; ++s) {
        const float phi = column_angle(s, segments);
        const float x = std::sin(phi), z = std::cos(phi);
        b.vertex({x * radius, y, z * radius}, n, {0.5f + 0.5f * x, 0.5f + 0.5f * z});
    }
    for (int s = 0; s < segments; ++s)
        b.triangle(centre, ring + static_cast<uint32_t>(s) + 1, ring + static_cast<uint32_t>(s));
}

}  // namespace

void add_flagpole(Builder& b, float radius, float height, int segments, int rings) {
    // `height` is the whole pole, tip included, centred on the origin like
    // every primitive. Seed 004: the tip's radius equals the pole's
    // diameter, so the hemisphere overhangs the pole and a flat, downward
    // shoulder (an annulus) closes it underneath.
    const float tip = 2 * radius;
    const float top = height / 2, bottom = -height / 2;
    const float centre = top - tip;
    const int bands = std::max(2, rings / 2);  // a hemisphere is half a sphere's rings
    // v runs along the surface from the tip (0) to the foot (1).
    const float arc = kPi / 2 * tip, shoulder = tip - radius, side = centre - bottom;
    const float length = arc + shoulder + side;
    std::vector<ProfilePoint> dome;
    for (int k = 0; k < bands; ++k) {
        const float theta = kPi / 2 * static_cast<float>(k) / static_cast<float>(bands);
        const float out = std::sin(theta), up = std::cos(theta);
        dome.push_back(
            {k == 0 ? 0.0f : tip * out, centre + tip * up, out, up, tip * theta / length});
    }
    dome.push_back({tip, centre, 1, 0, arc / length});  // the equator, exact
    add_revolved(b, dome, segments);
    // Three pieces, each with its own normals: the crease at the equator and
    // at the shoulder's inner edge stays sharp.
    add_revolved(
        b, {{tip, centre, 0, -1, arc / length}, {radius, centre, 0, -1, (arc + shoulder) / length}},
        segments);
    // The side in rows about a tip's diameter apart: per-vertex (Gouraud)
    // lighting and shadows are only as fine as the rows, and with only the
    // two end rings the shadow of the tip at the top and of the platform at
    // the foot would spread over the whole pole.
    const int rows = std::clamp(static_cast<int>(std::ceil(side / (2 * tip))), 1, 256);
    std::vector<ProfilePoint> column;
    for (int k = 0; k <= rows; ++k) {
        const float f = static_cast<float>(k) / static_cast<float>(rows);
        column.push_back({radius, k == rows ? bottom : centre - f * side, 1, 0,
                          (arc + shoulder + f * side) / length});
    }
    add_revolved(b, column, segments);
    add_bottom_cap(b, radius, bottom, segments);
}

namespace {

// The hole's rim: corner k at column_angle(k), direction (sin, cos) in
// (x, z), counter-clockwise seen from above.
void hole_rim(float hole_radius, int segments, std::vector<glm::vec2>& rim,
              std::vector<glm::vec2>& direction) {
    rim.resize(static_cast<size_t>(segments));
    direction.resize(rim.size());
    for (int k = 0; k < segments; ++k) {
        const float phi = column_angle(k, segments);
        direction[k] = {std::sin(phi), std::cos(phi)};
        rim[k] = hole_radius * direction[k];
    }
}

// A point of the square's outline; `corner` for one of its four corners.
struct OutlinePoint {
    glm::vec2 p;
    bool corner;
};

// The square's outline: each rim corner pushed out along its ray to the
// square, plus the square's four corners between them. The squares'
// corner m sits at 45 + 90 m degrees, an eighth-turn count of 1 + 2 m; it
// falls on rim corner k when segments (1 + 2 m) = 8 k, and strictly
// between k and k + 1 otherwise. `outline_of` maps rim corner k to its
// outline point.
std::vector<OutlinePoint> square_outline(float h, int segments,
                                         const std::vector<glm::vec2>& direction,
                                         std::vector<size_t>& outline_of) {
    std::vector<OutlinePoint> outline;
    outline_of.resize(direction.size());
    const glm::vec2 corners[4] = {{h, h}, {h, -h}, {-h, -h}, {-h, h}};
    for (int k = 0; k < segments; ++k) {
        glm::vec2 p;
        int on_corner = -1;
        for (int m = 0; m < 4; ++m)
            if (static_cast<long long>(segments) * (1 + 2 * m) == 8LL * k) on_corner = m;
        if (on_corner >= 0) {
            p = corners[on_corner];
        } else {
            const glm::vec2 d = direction[k];
            // Snap the coordinate that reaches the side to exactly +-h, so
            // the points of one side are coplanar with it.
            if (std::abs(d.x) >= std::abs(d.y))
                p = {std::copysign(h, d.x), std::clamp(d.y * (h / std::abs(d.x)), -h, h)};
            else
                p = {std::clamp(d.x * (h / std::abs(d.y)), -h, h), std::copysign(h, d.y)};
        }
        outline_of[k] = outline.size();
        outline.push_back({p, on_corner >= 0});
        for (int m = 0; m < 4; ++m) {
            const long long eighth = static_cast<long long>(segments) * (1 + 2 * m);
            if (8LL * k < eighth && eighth < 8LL * (k + 1)) outline.push_back({corners[m], true});
        }
    }
    return outline;
}

// The top's and bottom's texture coordinates: the square spans [0, 1], v
// mirrored on the bottom.
glm::vec2 slab_uv(glm::vec2 p, bool is_top, float size) {
    return glm::vec2(0.5f + p.x / size, is_top ? 0.5f + p.y / size : 0.5f - p.y / size);
}

// Top and bottom: for each rim edge k -> k + 1, the convex polygon rim
// k, its outline point, any square corner, the next outline point, rim
// k + 1 (the square cut by the wedge between the two rays and by the rim
// edge: convex), fanned from rim k. Counter-clockwise from above on top.
void add_slab_faces(Builder& b, float size, float top, float bottom, int segments,
                    const std::vector<glm::vec2>& rim, const std::vector<OutlinePoint>& outline,
                    const std::vector<size_t>& outline_of) {
    const glm::vec3 up(0, 1, 0), down(0, -1, 0);
    for (int face = 0; face < 2; ++face) {
        const bool is_top = face == 0;
        const float y = is_top ? top : bottom;
        for (int k = 0; k < segments; ++k) {
            const int next = (k + 1) % segments;
            std::vector<glm::vec2> polygon = {rim[k]};
            const size_t end = next == 0 ? outline.size() : outline_of[next];
            for (size_t i = outline_of[k]; i < end; ++i) polygon.push_back(outline[i].p);
            polygon.push_back(outline[end % outline.size()].p);
            polygon.push_back(rim[next]);
            std::vector<uint32_t> ids;
            for (const glm::vec2& p : polygon)
                ids.push_back(
                    b.vertex({p.x, y, p.y}, is_top ? up : down, slab_uv(p, is_top, size)));
            for (size_t i = 1; i + 1 < ids.size(); ++i) {
                if (is_top)
                    b.triangle(ids[0], ids[i], ids[i + 1]);
                else
                    b.triangle(ids[0], ids[i + 1], ids[i]);
            }
        }
    }
}

// The hole's wall: smooth, its normals towards the axis (away from the
// slab's material), wound the other way from a cylinder's side.
void add_hole_wall(Builder& b, float hole_radius, float top, float bottom, int segments) {
    const uint32_t wall = static_cast<uint32_t>(b.part.positions.size());
    for (int s = 0; s <= segments; ++s) {
        const float phi = column_angle(s, segments);
        const float x = std::sin(phi), z = std::cos(phi);
        const float u = static_cast<float>(s) / static_cast<float>(segments);
        b.vertex({x * hole_radius, bottom, z * hole_radius}, {-x, 0, -z}, {u, 1});
        b.vertex({x * hole_radius, top, z * hole_radius}, {-x, 0, -z}, {u, 0});
    }
    for (int s = 0; s < segments; ++s) {
        const uint32_t a = wall + 2 * static_cast<uint32_t>(s), c = a + 2;
        b.quad(a, a + 1, c + 1, c);
    }
}

// The four outer sides, flat, through every outline point so their
// edges are the top's and bottom's (no T-junctions: the mesh is closed).
void add_outer_sides(Builder& b, float size, float top, float bottom,
                     const std::vector<OutlinePoint>& outline) {
    float along = 0;
    for (size_t i = 0; i < outline.size(); ++i) {
        const glm::vec2 p = outline[i].p, q = outline[(i + 1) % outline.size()].p;
        // The side both points lie on: x = +-h or z = +-h.
        const glm::vec3 n =
            (p.x == q.x) ? glm::vec3(p.x > 0 ? 1 : -1, 0, 0) : glm::vec3(0, 0, p.y > 0 ? 1 : -1);
        const float length = glm::length(q - p);
        const float u0 = std::min(1.0f, along / (4 * size));
        const float u1 = std::min(1.0f, (along + length) / (4 * size));
        along += length;
        const uint32_t a = b.vertex({p.x, bottom, p.y}, n, {u0, 1});
        const uint32_t c = b.vertex({q.x, bottom, q.y}, n, {u1, 1});
        const uint32_t d = b.vertex({q.x, top, q.y}, n, {u1, 0});
        const uint32_t e = b.vertex({p.x, top, p.y}, n, {u0, 0});
        b.quad(a, c, d, e);
    }
}

}  // namespace

void add_platform(Builder& b, float size, float thickness, float hole_radius, int segments) {
    const float h = size / 2, top = thickness / 2, bottom = -thickness / 2;
    std::vector<glm::vec2> rim, direction;
    hole_rim(hole_radius, segments, rim, direction);
    std::vector<size_t> outline_of;
    const std::vector<OutlinePoint> outline = square_outline(h, segments, direction, outline_of);
    add_slab_faces(b, size, top, bottom, segments, rim, outline, outline_of);
    add_hole_wall(b, hole_radius, top, bottom, segments);
    add_outer_sides(b, size, top, bottom, outline);
}

}  // namespace facet::detail
