#include "shapes/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "shapes/primitive_builder.hpp"

namespace facet {
namespace detail {

uint32_t Builder::vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
    part.positions.push_back(p);
    part.normals.push_back(glm::normalize(n));
    part.uvs.push_back(uv);
    return static_cast<uint32_t>(part.positions.size() - 1);
}

void Builder::face(std::vector<glm::vec3> corners, std::vector<glm::vec2> uvs) {
    const size_t n = corners.size();
    glm::vec3 centre(0), area(0);
    for (size_t i = 0; i < n; ++i) {
        centre += corners[i];
        area += glm::cross(corners[i], corners[(i + 1) % n]);  // Newell
    }
    centre /= static_cast<float>(n);
    if (glm::dot(area, centre) < 0) {
        std::reverse(corners.begin(), corners.end());
        std::reverse(uvs.begin(), uvs.end());
        area = -area;
    }
    const glm::vec3 normal = glm::normalize(area);
    if (uvs.empty()) {
        // The first corner at the top of the texture, u to the right seen from outside.
        float r = 0;
        for (const auto& p : corners) r = std::max(r, glm::length(p - centre));
        glm::vec3 up = glm::normalize(corners[0] - centre);
        glm::vec3 right = glm::cross(up, normal);
        for (const auto& p : corners) {
            glm::vec3 d = (p - centre) / r;
            glm::vec2 uv(0.5f + 0.5f * glm::dot(d, right), 0.5f - 0.5f * glm::dot(d, up));
            uvs.push_back(glm::clamp(uv, glm::vec2(0), glm::vec2(1)));
        }
    }
    const uint32_t first = static_cast<uint32_t>(part.positions.size());
    for (size_t i = 0; i < n; ++i) vertex(corners[i], normal, uvs[i]);
    for (uint32_t i = 1; i + 1 < n; ++i) triangle(first, first + i, first + i + 1);
}

}  // namespace detail

namespace {

using detail::Builder;
using detail::kPi;

void add_plane(Builder& b, float size) {
    float h = size / 2;
    uint32_t a = b.vertex({-h, 0, h}, {0, 1, 0}, {0, 1});
    uint32_t c = b.vertex({h, 0, h}, {0, 1, 0}, {1, 1});
    uint32_t d = b.vertex({h, 0, -h}, {0, 1, 0}, {1, 0});
    uint32_t e = b.vertex({-h, 0, -h}, {0, 1, 0}, {0, 0});
    b.quad(a, c, d, e);
}

// Rows from the top (t = 0) round to `rows`, `columns` round the Y axis; each
// row has columns+1 vertices so the UV seam has its own column. `point`
// gives a position and normal for (column angle, row angle).
template <typename Point>
void add_grid(Builder& b, int columns, int rows, float row_span, Point point) {
    uint32_t first = static_cast<uint32_t>(b.part.positions.size());
    for (int r = 0; r <= rows; ++r) {
        float theta = row_span * static_cast<float>(r) / static_cast<float>(rows);
        for (int s = 0; s <= columns; ++s) {
            float phi = 2 * kPi * static_cast<float>(s) / static_cast<float>(columns);
            auto [p, n] = point(r, phi, theta);
            b.vertex(p, n, {static_cast<float>(s) / columns, static_cast<float>(r) / rows});
        }
    }
    auto at = [&](int r, int s) { return first + static_cast<uint32_t>(r * (columns + 1) + s); };
    const bool poles = row_span < 2 * kPi;  // a sphere closes at the poles, a torus round
    for (int r = 0; r < rows; ++r)
        for (int s = 0; s < columns; ++s) {
            if (poles && r == 0)
                b.triangle(at(0, s), at(1, s), at(1, s + 1));
            else if (poles && r == rows - 1)
                b.triangle(at(r, s), at(r + 1, s), at(r, s + 1));
            else
                b.quad(at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
        }
}

void add_sphere(Builder& b, float radius, int segments, int rings) {
    add_grid(b, segments, rings, kPi, [&](int r, float phi, float theta) {
        glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                    std::sin(theta) * std::cos(phi));
        if (r == 0) n = {0, 1, 0};
        if (r == rings) n = {0, -1, 0};
        return std::pair(n * radius, n);
    });
}

// A ring round the Y axis of radius `radius`; the tube's rings start at its
// top and turn outward first, so the winding is the sphere's.
void add_torus(Builder& b, float radius, float tube, int segments, int rings) {
    add_grid(b, segments, rings, 2 * kPi, [&](int, float phi, float theta) {
        glm::vec3 out(std::sin(phi), 0, std::cos(phi));
        glm::vec3 n = std::sin(theta) * out + glm::vec3(0, std::cos(theta), 0);
        return std::pair(radius * out + tube * n, n);
    });
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

[[noreturn]] void reject(const PrimitiveSpec& spec, const std::string& what) {
    throw Error(ExitCode::invalid_input, "primitive '" + spec.type + "': " + what);
}

template <typename T>
void require_range(const PrimitiveSpec& spec, const char* name, T value, T min, T max) {
    if (value >= min && value <= max) return;
    std::ostringstream s;
    s << name << " must be between " << min << " and " << max << ", got " << value;
    reject(spec, s.str());
}

void require_size(const PrimitiveSpec& spec, const char* name, float value) {
    // Sizes must be finite too: an infinite radius gives NaN normals and
    // infinite bounds that poison the camera framing downstream.
    if (value > 0 && std::isfinite(value)) return;
    std::ostringstream s;
    s << name << " must be finite and greater than 0, got " << value;
    reject(spec, s.str());
}

bool is_round(const std::string& type) {
    return type == "sphere" || type == "icosphere" || type == "torus" || type == "cylinder" ||
           type == "cone" || type == "flagpole" || type == "platform";
}

void validate(const PrimitiveSpec& spec) {
    require_size(spec, "size", spec.size);
    require_size(spec, "radius", spec.radius);
    require_size(spec, "height", spec.height);
    require_size(spec, "tube", spec.tube);
    require_size(spec, "thickness", spec.thickness);
    require_size(spec, "hole_radius", spec.hole_radius);
    for (int k = 0; k < 3; ++k) require_size(spec, "box size", spec.box_size[k]);
    // A scene file can ask for any tessellation; beyond this the vertex count
    // would overflow the index arithmetic or exhaust memory instead of failing cleanly.
    constexpr int kMaxDivisions = 65536;
    constexpr long long kMaxGridVertices = 1 << 24;
    require_range(spec, "segments", spec.segments, 3, kMaxDivisions);
    require_range(spec, "rings", spec.rings, spec.type == "torus" ? 3 : 2, kMaxDivisions);
    if ((static_cast<long long>(spec.segments) + 1) * (static_cast<long long>(spec.rings) + 1) >
        kMaxGridVertices)
        reject(spec, "segments and rings are too large (at most " +
                         std::to_string(kMaxGridVertices) + " grid vertices)");
    require_range(spec, "sides", spec.sides, 3, kMaxPrimitiveSides);
    if (spec.top_radius) {
        if (spec.type == "prism") require_size(spec, "top_radius", *spec.top_radius);
        if (!(*spec.top_radius >= 0 && *spec.top_radius <= 1e7f))
            reject(spec, "top_radius must be 0 or more");
    }
    require_range(spec, "subdivisions", spec.subdivisions, 0, kMaxIcosphereSubdivisions);
    if (spec.type == "torus" && !(spec.tube < spec.radius)) {
        std::ostringstream s;
        s << "tube (" << spec.tube << ") must be less than radius (" << spec.radius << ")";
        reject(spec, s.str());
    }
    if (spec.type == "flagpole" && !(spec.height > 2 * spec.radius)) {
        std::ostringstream s;
        s << "height (" << spec.height << ") must be greater than the tip's radius ("
          << 2 * spec.radius << ", the pole's diameter): the height includes the tip";
        reject(spec, s.str());
    }
    if (spec.type == "platform" && !(spec.hole_radius < spec.size / 2)) {
        std::ostringstream s;
        s << "hole_radius (" << spec.hole_radius << ") must be less than size / 2 ("
          << spec.size / 2 << ")";
        reject(spec, s.str());
    }
    if (spec.smooth.value_or(false) && !is_round(spec.type))
        reject(spec,
               "smooth applies only to sphere, icosphere, torus, cylinder, cone, flagpole "
               "and platform");
}

}  // namespace

Mesh make_primitive(const PrimitiveSpec& spec) {
    const std::string& t = spec.type;
    if (!(t == "plane" || t == "cube" || t == "box" || is_round(t) || t == "tetrahedron" ||
          t == "octahedron" || t == "icosahedron" || t == "dodecahedron" || t == "prism" ||
          t == "antiprism" || t == "pyramid"))
        throw Error(ExitCode::invalid_input, "unknown primitive type '" + t + "'");
    validate(spec);
    Builder b;
    if (t == "plane")
        add_plane(b, spec.size);
    else if (t == "cube")
        detail::add_box(b, glm::vec3(spec.size));
    else if (t == "box")
        detail::add_box(b, spec.box_size);
    else if (t == "sphere")
        add_sphere(b, spec.radius, spec.segments, spec.rings);
    else if (t == "icosphere")
        detail::add_icosphere(b, spec.radius, spec.subdivisions);
    else if (t == "torus")
        add_torus(b, spec.radius, spec.tube, spec.segments, spec.rings);
    else if (t == "cylinder") {
        add_side(b, spec.radius, spec.radius, spec.height, spec.segments);
        add_disc(b, spec.radius, spec.height / 2, spec.segments, true);
        add_disc(b, spec.radius, -spec.height / 2, spec.segments, false);
    } else if (t == "cone") {
        add_side(b, spec.radius, 0, spec.height, spec.segments);
        add_disc(b, spec.radius, -spec.height / 2, spec.segments, false);
    } else if (t == "prism")
        detail::add_frustum(b, spec.sides, spec.radius, spec.top_radius.value_or(spec.radius),
                            spec.height);
    else if (t == "antiprism")
        detail::add_antiprism(b, spec.sides, spec.radius, spec.height);
    else if (t == "pyramid")
        detail::add_frustum(b, spec.sides, spec.radius, spec.top_radius.value_or(0.0f),
                            spec.height);
    else if (t == "flagpole")
        detail::add_flagpole(b, spec.radius, spec.height, spec.segments, spec.rings);
    else if (t == "platform")
        detail::add_platform(b, spec.size, spec.thickness, spec.hole_radius, spec.segments);
    else
        detail::add_platonic(b, t, spec.radius);
    if (is_round(t) && !spec.smooth.value_or(true)) detail::make_faceted(b.part);
    Mesh mesh;
    mesh.source = "primitive " + t;
    mesh.loader = "facet";
    mesh.materials.push_back(Material{});
    mesh.parts.push_back(std::move(b.part));
    return mesh;
}

}  // namespace facet
