#include "assets/primitives.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/error.hpp"

namespace facet {
namespace {

constexpr float kPi = 3.14159265358979323846f;

struct Builder {
    MeshPart part;
    uint32_t vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
        part.positions.push_back(p);
        part.normals.push_back(glm::normalize(n));
        part.uvs.push_back(uv);
        return static_cast<uint32_t>(part.positions.size() - 1);
    }
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        part.indices.insert(part.indices.end(), {a, b, c});
    }
    // Quad a-b-c-d counter-clockwise seen from the front.
    void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }
};

void add_plane(Builder& b, float size) {
    float h = size / 2;
    uint32_t a = b.vertex({-h, 0, h}, {0, 1, 0}, {0, 1});
    uint32_t c = b.vertex({h, 0, h}, {0, 1, 0}, {1, 1});
    uint32_t d = b.vertex({h, 0, -h}, {0, 1, 0}, {1, 0});
    uint32_t e = b.vertex({-h, 0, -h}, {0, 1, 0}, {0, 0});
    b.quad(a, c, d, e);
}

void add_cube(Builder& b, float size) {
    float h = size / 2;
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

void add_sphere(Builder& b, float radius, int segments, int rings) {
    // Latitude rows from the north pole (row 0) to the south pole (row `rings`);
    // each row has segments+1 vertices so the UV seam has its own column.
    uint32_t first = static_cast<uint32_t>(b.part.positions.size());
    for (int r = 0; r <= rings; ++r) {
        float theta = kPi * static_cast<float>(r) / static_cast<float>(rings);
        for (int s = 0; s <= segments; ++s) {
            float phi = 2 * kPi * static_cast<float>(s) / static_cast<float>(segments);
            glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                        std::sin(theta) * std::cos(phi));
            if (r == 0) n = {0, 1, 0};
            if (r == rings) n = {0, -1, 0};
            b.vertex(n * radius, n,
                     {static_cast<float>(s) / segments, static_cast<float>(r) / rings});
        }
    }
    auto at = [&](int r, int s) { return first + static_cast<uint32_t>(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            if (r == 0)
                b.triangle(at(0, s), at(1, s), at(1, s + 1));
            else if (r == rings - 1)
                b.triangle(at(r, s), at(r + 1, s), at(r, s + 1));
            else
                b.quad(at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
        }
}

void add_disc(Builder& b, float radius, float y, int segments, bool up) {
    glm::vec3 n(0, up ? 1 : -1, 0);
    uint32_t centre = b.vertex({0, y, 0}, n, {0.5f, 0.5f});
    uint32_t ring = static_cast<uint32_t>(b.part.positions.size());
    for (int s = 0; s <= segments; ++s) {
        float phi = 2 * kPi * static_cast<float>(s) / static_cast<float>(segments);
        float x = std::sin(phi), z = std::cos(phi);
        b.vertex({x * radius, y, z * radius}, n, {0.5f + 0.5f * x, 0.5f - 0.5f * z});
    }
    for (int s = 0; s < segments; ++s) {
        if (up)
            b.triangle(centre, ring + s, ring + s + 1);
        else
            b.triangle(centre, ring + s + 1, ring + s);
    }
}

// Side of a cylinder or cone: radius_top == 0 gives a cone.
void add_side(Builder& b, float radius_bottom, float radius_top, float height, int segments) {
    float h = height / 2;
    float slope = (radius_bottom - radius_top) / height;  // normal tilts up by this for a cone
    uint32_t first = static_cast<uint32_t>(b.part.positions.size());
    for (int s = 0; s <= segments; ++s) {
        float phi = 2 * kPi * static_cast<float>(s) / static_cast<float>(segments);
        float x = std::sin(phi), z = std::cos(phi);
        glm::vec3 n(x, slope, z);
        float u = static_cast<float>(s) / segments;
        b.vertex({x * radius_bottom, -h, z * radius_bottom}, n, {u, 1});
        // At a cone's apex each segment keeps its own normal, so shading stays smooth.
        b.vertex({x * radius_top, h, z * radius_top}, n, {u, 0});
    }
    for (int s = 0; s < segments; ++s) {
        uint32_t a = first + 2 * s, c = first + 2 * (s + 1);
        if (radius_top > 0)
            b.quad(a, c, c + 1, a + 1);
        else
            b.triangle(a, c, a + 1);
    }
}

}  // namespace

Mesh make_primitive(const PrimitiveSpec& spec) {
    Builder b;
    // Sizes must be finite too: an infinite radius gives NaN normals and
    // infinite bounds that poison the camera framing downstream.
    auto positive = [](float v) { return v > 0 && std::isfinite(v); };
    if (spec.segments < 3 || spec.rings < 2 || !positive(spec.size) || !positive(spec.radius) ||
        !positive(spec.height))
        throw Error(ExitCode::invalid_input,
                    "primitive '" + spec.type +
                        "': sizes must be finite and > 0, segments >= 3, rings >= 2");
    // A scene file can ask for any tessellation; beyond this the vertex count
    // would overflow the index arithmetic or exhaust memory instead of failing cleanly.
    constexpr int kMaxDivisions = 65536;
    constexpr long long kMaxGridVertices = 1 << 24;
    if (spec.segments > kMaxDivisions || spec.rings > kMaxDivisions ||
        (static_cast<long long>(spec.segments) + 1) * (static_cast<long long>(spec.rings) + 1) >
            kMaxGridVertices)
        throw Error(ExitCode::invalid_input,
                    "primitive '" + spec.type + "': segments and rings are too large (at most " +
                        std::to_string(kMaxDivisions) + " each and " +
                        std::to_string(kMaxGridVertices) + " grid vertices)");
    if (spec.type == "plane")
        add_plane(b, spec.size);
    else if (spec.type == "cube")
        add_cube(b, spec.size);
    else if (spec.type == "sphere")
        add_sphere(b, spec.radius, spec.segments, spec.rings);
    else if (spec.type == "cylinder") {
        add_side(b, spec.radius, spec.radius, spec.height, spec.segments);
        add_disc(b, spec.radius, spec.height / 2, spec.segments, true);
        add_disc(b, spec.radius, -spec.height / 2, spec.segments, false);
    } else if (spec.type == "cone") {
        add_side(b, spec.radius, 0, spec.height, spec.segments);
        add_disc(b, spec.radius, -spec.height / 2, spec.segments, false);
    } else {
        throw Error(ExitCode::invalid_input, "unknown primitive type '" + spec.type + "'");
    }
    Mesh mesh;
    mesh.source = "primitive " + spec.type;
    mesh.materials.push_back(Material{});
    mesh.parts.push_back(std::move(b.part));
    return mesh;
}

}  // namespace facet
