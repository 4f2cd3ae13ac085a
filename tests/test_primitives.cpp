// Procedural meshes (src/shapes/primitives.cpp): counts from the parameters,
// unit outward normals, counter-clockwise winding, closed surfaces, and the
// areas and volumes of the shapes they approximate.
#include <catch2/catch.hpp>

#include <climits>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "asset_support.hpp"
#include "core/error.hpp"
#include "shapes/primitives.hpp"

using facet::test::centroid;
using facet::test::corner;
using facet::test::face_cross;
using facet::test::require_bounds;
using facet::test::require_closed_and_oriented;
using facet::test::require_normals_agree_with_winding;
using facet::test::surface_area;
using facet::test::Topology;

namespace {

constexpr double kPi = 3.14159265358979323846;

facet::PrimitiveSpec spec(const std::string& type, int segments = 32, int rings = 16) {
    facet::PrimitiveSpec s;
    s.type = type;
    s.segments = segments;
    s.rings = rings;
    return s;
}

const facet::MeshPart& only_part(const facet::Mesh& mesh) {
    REQUIRE(mesh.parts.size() == 1);
    return mesh.parts[0];
}

void check_attributes(const facet::Mesh& mesh) {
    const auto& part = only_part(mesh);
    REQUIRE(part.material < mesh.materials.size());
    REQUIRE(part.indices.size() % 3 == 0);
    REQUIRE(part.normals.size() == part.positions.size());
    REQUIRE(part.uvs.size() == part.positions.size());
    for (uint32_t i : part.indices) REQUIRE(i < part.positions.size());
    for (const auto& n : part.normals) CHECK(glm::length(n) == Approx(1.0f).margin(1e-5));
    for (const auto& uv : part.uvs) {
        CHECK(uv.x >= 0.0f);
        CHECK(uv.x <= 1.0f);
        CHECK(uv.y >= 0.0f);
        CHECK(uv.y <= 1.0f);
    }
    for (size_t t = 0; t < part.triangle_count(); ++t)
        CHECK(glm::length(face_cross(part, t)) > 0);  // no slivers
}

// Outward: for shapes convex around the origin, normals and faces point away from it.
void check_outward(const facet::MeshPart& part) {
    for (size_t i = 0; i < part.positions.size(); ++i)
        CHECK(glm::dot(part.normals[i], part.positions[i]) > 0);
    for (size_t t = 0; t < part.triangle_count(); ++t)
        CHECK(glm::dot(face_cross(part, t), centroid(part, t)) > 0);
}

// Signed volume by the divergence theorem: positive when faces point outward.
double signed_volume(const facet::MeshPart& part) {
    double v = 0;
    for (size_t t = 0; t < part.triangle_count(); ++t)
        v += glm::dot(corner(part, t, 0), glm::cross(corner(part, t, 1), corner(part, t, 2))) / 6.0;
    return v;
}

// Shapes round the Y axis: exact in y; the ring starts at +Z, so z reaches
// the radius exactly, and nothing lies outside the circle.
void require_round_bounds(const facet::Mesh& mesh, float radius, float half_height) {
    facet::Bounds b = mesh.bounds();
    CHECK(b.min.y == Approx(-half_height));
    CHECK(b.max.y == Approx(half_height));
    CHECK(b.max.z == Approx(radius));
    for (const auto& p : only_part(mesh).positions)
        CHECK(glm::length(glm::vec2(p.x, p.z)) <= radius * (1 + 1e-6f));
}

// Closed, consistently wound, and shaped like a sphere (Euler characteristic
// 2), with `vertices` distinct corners once seams are welded within `eps`.
void require_closed_sphere_like(const facet::Mesh& mesh, size_t vertices, float eps = 1e-5f) {
    Topology topo = require_closed_and_oriented(mesh, eps);
    CHECK(topo.vertices == vertices);
    CHECK(topo.vertices - topo.edges + topo.faces == 2);
}

// A cylinder or cone, with the checks every solid round the Y axis passes:
// attributes, outward faces, winding that agrees with the normals, bounds.
facet::Mesh round_solid(const std::string& type, int segments, float radius, float height) {
    facet::PrimitiveSpec s = spec(type, segments);
    s.radius = radius;
    s.height = height;
    facet::Mesh mesh = facet::make_primitive(s);
    check_attributes(mesh);
    check_outward(only_part(mesh));
    require_normals_agree_with_winding(only_part(mesh));
    require_round_bounds(mesh, radius, height / 2);
    return mesh;
}

void require_rejected(const facet::PrimitiveSpec& s) {
    try {
        facet::make_primitive(s);
        FAIL("expected facet::Error for type '" << s.type << "'");
    } catch (const facet::Error& e) {
        CHECK(e.code() == facet::ExitCode::invalid_input);
        CHECK(std::string(e.what()).size() > 0);
    }
}

}  // namespace

TEST_CASE("primitive plane", "[assets][primitives]") {
    facet::PrimitiveSpec s = spec("plane");
    s.size = 3;
    facet::Mesh mesh = facet::make_primitive(s);
    check_attributes(mesh);
    const auto& part = only_part(mesh);
    CHECK(mesh.triangle_count() == 2);
    CHECK(part.positions.size() == 4);
    require_bounds(mesh, {-1.5f, 0, -1.5f}, {1.5f, 0, 1.5f});
    for (const auto& n : part.normals) CHECK(n == glm::vec3(0, 1, 0));
    for (size_t t = 0; t < 2; ++t) CHECK(glm::normalize(face_cross(part, t)).y == Approx(1.0f));
    CHECK(surface_area(part) == Approx(9.0));
    require_normals_agree_with_winding(part);
    // The four corners get the four corners of texture space.
    std::map<std::pair<float, float>, int> uv_corners;
    for (const auto& uv : part.uvs) ++uv_corners[{uv.x, uv.y}];
    CHECK(uv_corners.size() == 4);
}

TEST_CASE("primitive cube", "[assets][primitives]") {
    for (float size : {1.0f, 2.5f}) {
        DYNAMIC_SECTION("size " << size) {
            facet::PrimitiveSpec s = spec("cube");
            s.size = size;
            facet::Mesh mesh = facet::make_primitive(s);
            check_attributes(mesh);
            const auto& part = only_part(mesh);
            CHECK(mesh.triangle_count() == 12);
            CHECK(part.positions.size() == 24);  // four per face, for sharp normals and own UVs
            const float h = size / 2;
            require_bounds(mesh, glm::vec3(-h), glm::vec3(h));
            check_outward(part);
            require_normals_agree_with_winding(part);
            for (const auto& n : part.normals)
                CHECK(std::abs(n.x) + std::abs(n.y) + std::abs(n.z) == Approx(1.0f));
            require_closed_sphere_like(mesh, 8);
            CHECK(surface_area(part) == Approx(6.0 * size * size));
            CHECK(signed_volume(part) == Approx(double(size) * size * size));
        }
    }
}

TEST_CASE("primitive sphere", "[assets][primitives]") {
    struct Case {
        int segments, rings;
        float radius;
    };
    for (const Case c :
         {Case{3, 2, 1.0f}, Case{8, 4, 0.5f}, Case{32, 16, 2.0f}, Case{7, 5, 1.0f}}) {
        DYNAMIC_SECTION(c.segments << " segments, " << c.rings << " rings, radius " << c.radius) {
            facet::PrimitiveSpec s = spec("sphere", c.segments, c.rings);
            s.radius = c.radius;
            facet::Mesh mesh = facet::make_primitive(s);
            check_attributes(mesh);
            const auto& part = only_part(mesh);
            // One triangle per segment in each polar cap, two per segment in the other rings.
            CHECK(mesh.triangle_count() == static_cast<size_t>(2 * c.segments * (c.rings - 1)));
            check_outward(part);
            require_normals_agree_with_winding(part);
            for (size_t i = 0; i < part.positions.size(); ++i) {
                CHECK(glm::length(part.positions[i]) == Approx(c.radius).epsilon(1e-5));
                // Smooth: the normal is the radial direction.
                CHECK(glm::dot(part.normals[i], part.positions[i] / c.radius) ==
                      Approx(1.0f).margin(1e-5));
            }
            require_closed_sphere_like(mesh, static_cast<size_t>(c.segments * (c.rings - 1) + 2),
                                       1e-5f * c.radius);
            CHECK(signed_volume(part) > 0);
            facet::Bounds b = mesh.bounds();
            CHECK(b.max.y == Approx(c.radius));
            CHECK(b.min.y == Approx(-c.radius));
        }
    }
    SECTION("fine tessellation approaches the true area and volume") {
        facet::PrimitiveSpec s = spec("sphere", 128, 64);
        s.radius = 1.5f;
        facet::Mesh mesh = facet::make_primitive(s);
        const auto& part = only_part(mesh);
        CHECK(surface_area(part) == Approx(4 * kPi * 1.5 * 1.5).epsilon(0.005));
        CHECK(signed_volume(part) == Approx(4.0 / 3.0 * kPi * 1.5 * 1.5 * 1.5).epsilon(0.005));
    }
}

TEST_CASE("primitive cylinder", "[assets][primitives]") {
    for (int segments : {3, 6, 33}) {
        DYNAMIC_SECTION(segments << " segments") {
            facet::Mesh mesh = round_solid("cylinder", segments, 0.75f, 3.0f);
            const auto& part = only_part(mesh);
            // Side: two per segment; each cap: one per segment.
            CHECK(mesh.triangle_count() == static_cast<size_t>(4 * segments));
            for (size_t i = 0; i < part.positions.size(); ++i) {
                const auto& n = part.normals[i];
                const auto& p = part.positions[i];
                if (std::abs(n.y) > 0.5f) {  // cap: flat, at the matching end
                    CHECK(std::abs(n.y) == Approx(1.0f));
                    CHECK(p.y == Approx(n.y * 1.5f));
                } else {  // side: horizontal, radial
                    CHECK(n.y == Approx(0.0f).margin(1e-6));
                    CHECK(glm::length(glm::vec2(p.x, p.z)) == Approx(0.75f));
                    CHECK(glm::dot(n, glm::normalize(glm::vec3(p.x, 0, p.z))) ==
                          Approx(1.0f).margin(1e-5));
                }
            }
            require_closed_sphere_like(mesh, static_cast<size_t>(2 * segments + 2));
            // The inscribed prism: n triangles of the polygon times the height.
            double polygon = 0.5 * segments * 0.75 * 0.75 * std::sin(2 * kPi / segments);
            CHECK(signed_volume(part) == Approx(polygon * 3.0).epsilon(1e-4));
        }
    }
}

TEST_CASE("primitive cone", "[assets][primitives]") {
    for (int segments : {3, 5, 48}) {
        DYNAMIC_SECTION(segments << " segments") {
            facet::Mesh mesh = round_solid("cone", segments, 1.0f, 2.0f);
            const auto& part = only_part(mesh);
            // Side: one triangle per segment up to the apex; base: one per segment.
            CHECK(mesh.triangle_count() == static_cast<size_t>(2 * segments));
            // The side's normals lean up by the slope: n.y / |n.xz| = radius / height.
            for (size_t i = 0; i < part.positions.size(); ++i) {
                const auto& n = part.normals[i];
                if (n.y > -0.99f) {
                    float horizontal = glm::length(glm::vec2(n.x, n.z));
                    CHECK(n.y / horizontal == Approx(0.5f).epsilon(1e-4));
                }
            }
            // The ring, the apex and the base centre.
            require_closed_sphere_like(mesh, static_cast<size_t>(segments + 2));
            double polygon = 0.5 * segments * std::sin(2 * kPi / segments);
            CHECK(signed_volume(part) == Approx(polygon * 2.0 / 3.0).epsilon(1e-4));
        }
    }
}

TEST_CASE("primitive sources and materials", "[assets][primitives]") {
    for (const std::string type : {"plane", "cube", "sphere", "cylinder", "cone"}) {
        DYNAMIC_SECTION(type) {
            facet::Mesh mesh = facet::make_primitive(spec(type));
            CHECK_THAT(mesh.source, Catch::Contains(type));
            REQUIRE(mesh.materials.size() == 1);
            CHECK(only_part(mesh).material == 0);
            CHECK(mesh.warnings.empty());
        }
    }
}

TEST_CASE("primitive parameters out of range are errors", "[assets][primitives]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    require_rejected(spec("teapot"));
    require_rejected(spec(""));
    require_rejected(spec("Cube "));
    for (const std::string type : {"plane", "cube", "sphere", "cylinder", "cone"}) {
        DYNAMIC_SECTION(type) {
            require_rejected(spec(type, 2));
            require_rejected(spec(type, -5));
            require_rejected(spec(type, 32, 1));
            for (float bad : {0.0f, -1.0f, nan, inf})
                for (float facet::PrimitiveSpec::*field :
                     {&facet::PrimitiveSpec::size, &facet::PrimitiveSpec::radius,
                      &facet::PrimitiveSpec::height}) {
                    facet::PrimitiveSpec s = spec(type);
                    s.*field = bad;
                    require_rejected(s);
                }
            // Tessellation so fine it could only exhaust memory.
            require_rejected(spec(type, INT_MAX, 16));
            require_rejected(spec(type, 32, INT_MAX));
            require_rejected(spec(type, 1 << 20, 1 << 20));
        }
    }
}

TEST_CASE("primitive with generous but sane tessellation is accepted", "[assets][primitives]") {
    facet::Mesh mesh = facet::make_primitive(spec("sphere", 512, 256));
    CHECK(mesh.triangle_count() == static_cast<size_t>(2 * 512 * 255));
}
