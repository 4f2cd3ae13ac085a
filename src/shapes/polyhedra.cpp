// The faceted procedural solids (box, Platonic solids, prism, antiprism,
// pyramid) and the icosphere. Every face of a faceted solid has its own
// corners, so its normal is flat; the primitive types are in primitives.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>

#include "shapes/primitive_builder.hpp"

namespace facet::detail {
namespace {

using Triangles = std::vector<std::array<int, 3>>;

// Unit icosahedron with a vertex at each pole (0, +-1, 0) and two rings of
// five at y = +-1/sqrt(5); the upper ring starts on +Z, the lower is turned
// half a step. Triangles are wound outward.
void unit_icosahedron(std::vector<glm::vec3>& v, Triangles& t) {
    const float y = 1 / std::sqrt(5.0f), r = 2 / std::sqrt(5.0f);
    v = {{0, 1, 0}, {0, -1, 0}};
    for (int ring = 0; ring < 2; ++ring)
        for (int k = 0; k < 5; ++k) {
            float phi = 2 * kPi * (static_cast<float>(k) + 0.5f * static_cast<float>(ring)) / 5;
            v.push_back({r * std::sin(phi), ring == 0 ? y : -y, r * std::cos(phi)});
        }
    auto up = [](int k) { return 2 + k % 5; };
    auto low = [](int k) { return 7 + k % 5; };
    for (int k = 0; k < 5; ++k) {
        t.push_back({0, up(k), up(k + 1)});
        t.push_back({up(k), low(k), up(k + 1)});
        t.push_back({up(k + 1), low(k), low(k + 1)});
        t.push_back({1, low(k + 1), low(k)});
    }
    for (auto& tri : t) {  // wind outward (the solid is convex around the origin)
        glm::vec3 a = v[tri[0]], b = v[tri[1]], c = v[tri[2]];
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0) std::swap(tri[1], tri[2]);
    }
}

void faces_of(Builder& b, const std::vector<glm::vec3>& v,
              const std::vector<std::vector<int>>& faces) {
    for (const auto& f : faces) {
        std::vector<glm::vec3> corners;
        for (int i : f) corners.push_back(v[i]);
        b.face(std::move(corners));
    }
}

// The dodecahedron is the icosahedron's dual: a corner at the centre of each
// triangle (pushed out to the sphere), a pentagon round each vertex.
void add_dodecahedron(Builder& b, float radius) {
    std::vector<glm::vec3> ico;
    Triangles tris;
    unit_icosahedron(ico, tris);
    std::vector<glm::vec3> v;
    for (const auto& t : tris) v.push_back(glm::normalize(ico[t[0]] + ico[t[1]] + ico[t[2]]));
    std::vector<std::vector<int>> faces;
    for (size_t i = 0; i < ico.size(); ++i) {
        glm::vec3 axis = ico[i];
        std::vector<std::pair<float, int>> around;
        glm::vec3 e1(0), e2(0);
        for (size_t t = 0; t < tris.size(); ++t) {
            if (std::find(tris[t].begin(), tris[t].end(), static_cast<int>(i)) == tris[t].end())
                continue;
            glm::vec3 d = v[t] - axis * glm::dot(v[t], axis);
            if (around.empty()) {
                e1 = glm::normalize(d);
                e2 = glm::cross(axis, e1);
            }
            around.push_back({std::atan2(glm::dot(d, e2), glm::dot(d, e1)), static_cast<int>(t)});
        }
        std::sort(around.begin(), around.end());
        std::vector<int> face;
        for (const auto& a : around) face.push_back(a.second);
        faces.push_back(face);
    }
    for (auto& p : v) p *= radius;
    faces_of(b, v, faces);
}

glm::vec3 on_circle(float radius, float phi, float y) {
    return {radius * std::sin(phi), y, radius * std::cos(phi)};
}

float angle(int k, int sides, float offset = 0) {
    return 2 * kPi * (static_cast<float>(k) + offset) / static_cast<float>(sides);
}

float fraction(float k, int sides) {
    return k / static_cast<float>(sides);
}

// A regular polygon in the plane y, its UVs projected from above.
void add_cap(Builder& b, int sides, float radius, float y, float offset = 0) {
    std::vector<glm::vec3> corners;
    std::vector<glm::vec2> uvs;
    for (int k = 0; k < sides; ++k) {
        float phi = angle(k, sides, offset);
        corners.push_back(on_circle(radius, phi, y));
        uvs.push_back({0.5f + 0.5f * std::sin(phi), 0.5f - 0.5f * std::cos(phi)});
    }
    b.face(std::move(corners), std::move(uvs));
}

}  // namespace

void add_box(Builder& b, glm::vec3 size) {
    glm::vec3 h = size / 2.0f;
    // For each face: outward normal and two in-plane axes with u x v = normal.
    const glm::vec3 faces[6][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    for (const auto& f : faces) {
        glm::vec3 n = f[0], u = f[1], v = f[2];
        uint32_t a = b.vertex((n - u - v) * h, n, {0, 1});
        uint32_t c = b.vertex((n + u - v) * h, n, {1, 1});
        uint32_t d = b.vertex((n + u + v) * h, n, {1, 0});
        uint32_t e = b.vertex((n - u + v) * h, n, {0, 0});
        b.quad(a, c, d, e);
    }
}

void add_platonic(Builder& b, const std::string& type, float radius) {
    std::vector<glm::vec3> v;
    std::vector<std::vector<int>> faces;
    if (type == "tetrahedron") {
        // A vertex up, the base triangle level at y = -radius / 3.
        v.push_back({0, 1, 0});
        for (int k = 0; k < 3; ++k)
            v.push_back(on_circle(std::sqrt(8.0f) / 3, angle(k, 3), -1.0f / 3));
        faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 2, 3}};
    } else if (type == "octahedron") {
        v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (int x : {0, 1})
            for (int y : {2, 3})
                for (int z : {4, 5}) faces.push_back({x, y, z});
    } else if (type == "icosahedron") {
        Triangles tris;
        unit_icosahedron(v, tris);
        for (const auto& t : tris) faces.push_back({t[0], t[1], t[2]});
    } else {
        add_dodecahedron(b, radius);
        return;
    }
    for (auto& p : v) p *= radius;
    faces_of(b, v, faces);
}

void add_frustum(Builder& b, int sides, float bottom, float top, float height) {
    const float h = height / 2;
    for (int k = 0; k < sides; ++k) {
        const float fk = static_cast<float>(k);
        const float p0 = angle(k, sides), p1 = angle(k + 1, sides);
        const glm::vec3 b0 = on_circle(bottom, p0, -h), b1 = on_circle(bottom, p1, -h);
        if (top > 0) {
            // Both ends' corners sit at the same angles, so each side is a
            // planar trapezoid (a rectangle for a prism).
            b.face({b0, b1, on_circle(top, p1, h), on_circle(top, p0, h)},
                   {{fraction(fk, sides), 1},
                    {fraction(fk + 1, sides), 1},
                    {fraction(fk + 1, sides), 0},
                    {fraction(fk, sides), 0}});
        } else {
            b.face({b0, b1, glm::vec3(0, h, 0)}, {{fraction(fk, sides), 1},
                                                  {fraction(fk + 1, sides), 1},
                                                  {fraction(fk + 0.5f, sides), 0}});
        }
    }
    if (top > 0) add_cap(b, sides, top, h);
    add_cap(b, sides, bottom, -h);
}

void add_antiprism(Builder& b, int sides, float radius, float height) {
    // The top polygon is turned half a step; u runs once round from +Z, so
    // the last triangle reaches half a step past 1 (continuous with wrap: repeat).
    const float h = height / 2;
    for (int k = 0; k < sides; ++k) {
        float fk = static_cast<float>(k);
        glm::vec3 b0 = on_circle(radius, angle(k, sides), -h);
        glm::vec3 b1 = on_circle(radius, angle(k + 1, sides), -h);
        glm::vec3 t0 = on_circle(radius, angle(k, sides, 0.5f), h);
        glm::vec3 t1 = on_circle(radius, angle(k + 1, sides, 0.5f), h);
        b.face({b0, b1, t0}, {{fraction(fk, sides), 1},
                              {fraction(fk + 1, sides), 1},
                              {fraction(fk + 0.5f, sides), 0}});
        b.face({t0, b1, t1}, {{fraction(fk + 0.5f, sides), 0},
                              {fraction(fk + 1, sides), 1},
                              {fraction(fk + 1.5f, sides), 0}});
    }
    add_cap(b, sides, radius, h, 0.5f);
    add_cap(b, sides, radius, -h);
}

void add_icosphere(Builder& b, float radius, int subdivisions) {
    std::vector<glm::vec3> v;
    Triangles tris;
    unit_icosahedron(v, tris);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<int, int>, int> middle;
        auto mid = [&](int i, int j) {
            auto key = std::minmax(i, j);
            auto [it, added] = middle.try_emplace(key, static_cast<int>(v.size()));
            if (added) v.push_back(glm::normalize(v[i] + v[j]));
            return it->second;
        };
        Triangles finer;
        finer.reserve(tris.size() * 4);
        for (const auto& [a, c, d] : tris) {  // each split in four, winding kept
            int ac = mid(a, c), cd = mid(c, d), da = mid(d, a);
            finer.push_back({a, ac, da});
            finer.push_back({c, cd, ac});
            finer.push_back({d, da, cd});
            finer.push_back({ac, cd, da});
        }
        tris = std::move(finer);
    }
    // UVs as on the UV sphere: u once round from +Z (atan2(x, z)), v from the
    // north pole (0) to the south pole (1). A triangle across the seam gets
    // its own corners with u past 1; a pole corner takes the mean u of the
    // triangle's other two, so each pole triangle has its own.
    auto u_of = [](glm::vec3 p) {
        float u = std::atan2(p.x, p.z) / (2 * kPi);
        if (u < 0) u += 1;
        return u > 1 - 1e-6f ? 0.0f : u;  // rounding just west of the seam is on it
    };
    auto at_pole = [](glm::vec3 p) { return std::abs(p.x) < 1e-6f && std::abs(p.z) < 1e-6f; };
    std::map<std::tuple<int, float, float>, uint32_t> made;
    for (const auto& t : tris) {
        glm::vec2 uv[3];
        for (int k = 0; k < 3; ++k) {
            glm::vec3 p = v[t[k]];
            uv[k] = {at_pole(p) ? 0.0f : u_of(p), std::acos(std::clamp(p.y, -1.0f, 1.0f)) / kPi};
        }
        float lo = 2, hi = -1;
        for (int k = 0; k < 3; ++k)
            if (!at_pole(v[t[k]])) lo = std::min(lo, uv[k].x), hi = std::max(hi, uv[k].x);
        for (int k = 0; k < 3; ++k)
            if (!at_pole(v[t[k]]) && hi - lo > 0.5f && uv[k].x < 0.5f) uv[k].x += 1;
        for (int k = 0; k < 3; ++k)
            if (at_pole(v[t[k]])) uv[k].x = (uv[(k + 1) % 3].x + uv[(k + 2) % 3].x) / 2;
        uint32_t index[3];
        for (int k = 0; k < 3; ++k) {
            auto [it, added] = made.try_emplace({t[k], uv[k].x, uv[k].y}, 0);
            if (added) it->second = b.vertex(v[t[k]] * radius, v[t[k]], uv[k]);
            index[k] = it->second;
        }
        b.triangle(index[0], index[1], index[2]);
    }
}

void make_faceted(MeshPart& part) {
    MeshPart flat;
    flat.material = part.material;
    for (size_t t = 0; t < part.triangle_count(); ++t) {
        const uint32_t* i = &part.indices[3 * t];
        glm::vec3 n = glm::normalize(glm::cross(part.positions[i[1]] - part.positions[i[0]],
                                                part.positions[i[2]] - part.positions[i[0]]));
        for (int k = 0; k < 3; ++k) {
            flat.indices.push_back(static_cast<uint32_t>(flat.positions.size()));
            flat.positions.push_back(part.positions[i[k]]);
            flat.normals.push_back(n);
            if (!part.uvs.empty()) flat.uvs.push_back(part.uvs[i[k]]);
        }
    }
    part = std::move(flat);
}

}  // namespace facet::detail
