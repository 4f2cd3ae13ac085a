// The flag scene's primitives (src/shapes/flag_primitives.cpp): the flagpole
// (cylinder with a hemispherical tip) and the platform (a slab with a round
// hole through it). Closed, outward-facing, the right topology (a sphere's
// and a torus's), the sizes asked for, the hole kept clear, and a pole that
// fits its hole exactly.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "asset_support.hpp"
#include "core/error.hpp"
#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "shapes/primitives.hpp"
#include "support.hpp"

using facet::test::face_cross;
using facet::test::require_bounds;
using facet::test::require_closed_and_oriented;
using facet::test::require_normals_agree_with_winding;
using facet::test::Topology;

namespace {

constexpr double kPi = 3.14159265358979323846;

facet::Mesh pole(float radius, float height, int segments = 32, int rings = 16) {
    facet::PrimitiveSpec s;
    s.type = "flagpole";
    s.radius = radius;
    s.height = height;
    s.segments = segments;
    s.rings = rings;
    return facet::make_primitive(s);
}

facet::Mesh platform(float size, float thickness, float hole, int segments = 32) {
    facet::PrimitiveSpec s;
    s.type = "platform";
    s.size = size;
    s.thickness = thickness;
    s.hole_radius = hole;
    s.segments = segments;
    return facet::make_primitive(s);
}

// Signed volume by the divergence theorem: positive when the faces point out.
double signed_volume(const facet::MeshPart& part) {
    double sum = 0;
    for (size_t t = 0; t < part.triangle_count(); ++t) {
        const glm::dvec3 a = facet::test::corner(part, t, 0), b = facet::test::corner(part, t, 1),
                         c = facet::test::corner(part, t, 2);
        sum += glm::dot(a, glm::cross(b, c)) / 6;
    }
    return sum;
}

long euler(const Topology& t) {
    return static_cast<long>(t.vertices) - static_cast<long>(t.edges) + static_cast<long>(t.faces);
}

// Unit normals, UVs in [0, 1], no zero-area triangles.
void check_attributes(const facet::MeshPart& part) {
    REQUIRE(part.normals.size() == part.positions.size());
    REQUIRE(part.uvs.size() == part.positions.size());
    for (const auto& n : part.normals) CHECK(glm::length(n) == Approx(1.0f).margin(1e-5));
    for (const auto& uv : part.uvs) {
        CHECK(uv.x >= 0.0f);
        CHECK(uv.x <= 1.0f);
        CHECK(uv.y >= 0.0f);
        CHECK(uv.y <= 1.0f);
    }
    for (size_t t = 0; t < part.triangle_count(); ++t) CHECK(glm::length(face_cross(part, t)) > 0);
}

// The polygon of n corners inscribed in a circle of radius r.
double polygon_area(double r, int n) {
    return 0.5 * n * r * r * std::sin(2 * kPi / n);
}

}  // namespace

TEST_CASE("flagpole is a closed, outward cylinder with a tip of the pole's diameter",
          "[primitives]") {
    const float r = 0.05f, h = 6;
    const int segments = GENERATE(3, 8, 32);
    const int rings = GENERATE(2, 16);
    INFO("segments " << segments << ", rings " << rings);
    const facet::Mesh mesh = pole(r, h, segments, rings);
    REQUIRE(mesh.parts.size() == 1);
    const facet::MeshPart& part = mesh.parts[0];
    check_attributes(part);
    // Closed and consistently wound, with a sphere's topology.
    const Topology t = require_closed_and_oriented(mesh, 1e-6f);
    CHECK(euler(t) == 2);
    require_normals_agree_with_winding(part);
    // Centred, `height` in all with the tip. Seed 004: the tip's radius is
    // the pole's diameter, so the pole is as wide as 2r at the tip (exactly
    // when the polygon has corners on both axes) and r below it.
    const float tip = 2 * r, centre = h / 2 - tip;
    const facet::Bounds b = mesh.bounds();
    CHECK(b.min.y == Approx(-h / 2).margin(1e-6));
    CHECK(b.max.y == Approx(h / 2).margin(1e-6));
    for (const auto& q : part.positions) {
        const float limit = q.y < centre - 1e-6f ? r : tip;
        CHECK(q.x * q.x + q.z * q.z <= limit * limit * 1.00001f);
    }
    if (segments % 4 == 0) require_bounds(mesh, {-tip, -h / 2, -tip}, {tip, h / 2, tip}, 1e-6f);
    // Outward, and the volume of the prism plus the tip it approximates: a
    // cylinder of the polygon's area below the tip's centre, and at most a
    // hemisphere of radius 2r above it.
    const double volume = signed_volume(part);
    const double cylinder = polygon_area(r, segments) * (h / 2 - tip + h / 2);
    const double hemisphere = 2.0 / 3.0 * kPi * tip * tip * tip;
    CHECK(volume > cylinder);
    CHECK(volume < cylinder + hemisphere);
    if (segments == 32 && rings == 16)
        CHECK(volume == Approx(kPi * r * r * (h - tip) + hemisphere).epsilon(0.01));
}

TEST_CASE("flagpole normals: a smooth side, a flat shoulder, a round tip", "[primitives]") {
    const float r = 0.5f, h = 4, tip = 2 * r;
    const facet::Mesh mesh = pole(r, h);
    const facet::MeshPart& part = mesh.parts[0];
    const float centre = h / 2 - tip;
    int shoulder = 0;
    for (size_t i = 0; i < part.positions.size(); ++i) {
        const glm::vec3 p = part.positions[i], n = part.normals[i];
        const float out_radius = std::sqrt(p.x * p.x + p.z * p.z);
        INFO("vertex " << i << " at (" << p.x << ", " << p.y << ", " << p.z << ")");
        if (p.y <= -h / 2 + 1e-6f && n.y < -0.5f) {
            CHECK(n == glm::vec3(0, -1, 0));  // the foot is flat
        } else if (std::abs(p.y - centre) < 1e-6f && n.y < -0.5f) {
            // The shoulder under the tip faces down, from r out to 2r.
            CHECK(n == glm::vec3(0, -1, 0));
            CHECK(out_radius >= r * 0.99999f);
            CHECK(out_radius <= tip * 1.00001f);
            ++shoulder;
        } else if (p.y <= centre + 1e-6f && out_radius < r * 1.00001f) {
            // The side: horizontal normals straight out.
            const glm::vec3 out = glm::normalize(glm::vec3(p.x, 0, p.z));
            CHECK(glm::length(n - out) < 1e-5f);
        } else {
            // The tip: the sphere's normal about its centre, radius 2r.
            const glm::vec3 out = glm::normalize(p - glm::vec3(0, centre, 0));
            CHECK(glm::length(n - out) < 1e-5f);
            CHECK(glm::length(p - glm::vec3(0, centre, 0)) == Approx(tip).margin(1e-5));
        }
    }
    CHECK(shoulder > 0);
}

TEST_CASE("platform is a closed slab with a through-hole: a torus's topology", "[primitives]") {
    const float size = 2, thickness = 0.2f, hole = 0.05f;
    // Counts where the square's corners fall between the rim's corners (3,
    // 4, 5, 12, 33) and on them (8, 16, 32).
    const int segments = GENERATE(3, 4, 5, 8, 12, 16, 32, 33);
    INFO("segments " << segments);
    const facet::Mesh mesh = platform(size, thickness, hole, segments);
    REQUIRE(mesh.parts.size() == 1);
    const facet::MeshPart& part = mesh.parts[0];
    check_attributes(part);
    const Topology t = require_closed_and_oriented(mesh, 1e-6f);
    CHECK(euler(t) == 0);  // genus 1: the hole goes through
    require_normals_agree_with_winding(part);
    require_bounds(mesh, {-size / 2, -thickness / 2, -size / 2},
                   {size / 2, thickness / 2, size / 2}, 1e-6f);
    // Outward, and exactly the slab less the hole's prism.
    const double volume = (size * size - polygon_area(hole, segments)) * thickness;
    CHECK(signed_volume(part) == Approx(volume).epsilon(1e-5));

    const float top = thickness / 2;
    size_t rim = 0;
    for (size_t i = 0; i < part.positions.size(); ++i) {
        const glm::vec3 p = part.positions[i], n = part.normals[i];
        const float from_axis = std::sqrt(p.x * p.x + p.z * p.z);
        INFO("vertex " << i << " at (" << p.x << ", " << p.y << ", " << p.z << ")");
        // Nothing inside the hole: every vertex is at least the hole's radius
        // from the axis.
        CHECK(from_axis >= hole - 1e-6f);
        const bool flat_face = n.y == 1 || n.y == -1;
        if (flat_face) {
            CHECK(std::abs(p.y) == top);  // top and bottom are flat
        } else if (from_axis < hole + 1e-5f) {
            // The hole's wall: smooth, pointing at the axis.
            ++rim;
            CHECK(n.y == 0);
            CHECK(glm::length(n + glm::vec3(p.x, 0, p.z) / from_axis) < 1e-5f);
        } else {
            // The outer sides: flat, on the square, pointing straight out.
            const bool x_side = std::abs(n.x) == 1, z_side = std::abs(n.z) == 1;
            CHECK((x_side || z_side));
            if (x_side) CHECK(p.x == n.x * size / 2);
            if (z_side) CHECK(p.z == n.z * size / 2);
        }
    }
    CHECK(rim == static_cast<size_t>(2 * (segments + 1)));
}

TEST_CASE("a flagpole fits its platform's hole exactly", "[primitives]") {
    const float r = 0.04f;
    const int segments = GENERATE(6, 32);
    const facet::Mesh pole_mesh = pole(r, 6, segments),
                      slab_mesh = platform(1.5f, 0.2f, r, segments);
    const facet::MeshPart& p = pole_mesh.parts[0];
    const facet::MeshPart& slab = slab_mesh.parts[0];
    // Every corner of the hole's rim is a corner of the pole's side, in x and z.
    size_t matched = 0;
    for (size_t i = 0; i < slab.positions.size(); ++i) {
        const glm::vec3 q = slab.positions[i];
        if (std::sqrt(q.x * q.x + q.z * q.z) > r + 1e-6f) continue;
        bool found = false;
        for (const glm::vec3& s : p.positions) found = found || (s.x == q.x && s.z == q.z);
        CHECK(found);
        ++matched;
    }
    CHECK(matched > static_cast<size_t>(2 * segments));
}

TEST_CASE("flagpole and platform can be faceted and stay closed", "[primitives]") {
    for (const char* type : {"flagpole", "platform"}) {
        INFO(type);
        facet::PrimitiveSpec s;
        s.type = type;
        s.smooth = false;
        s.segments = 12;
        s.radius = 0.05f;  // the scene's default for a flagpole (a platform ignores it)
        const facet::Mesh mesh = facet::make_primitive(s);
        const Topology t = require_closed_and_oriented(mesh, 1e-6f);
        CHECK(euler(t) == (std::string(type) == "flagpole" ? 2 : 0));
        require_normals_agree_with_winding(mesh, 0.999f);  // flat: each normal its face's
    }
}

TEST_CASE("flagpole and platform reject sizes that cannot be built", "[primitives]") {
    using facet::test::require_input_error;
    facet::PrimitiveSpec s;
    s.type = "flagpole";
    s.radius = 1;
    s.height = 2;
    require_input_error(
        [&] { facet::make_primitive(s); },
        "primitive 'flagpole': height (2) must be greater than the tip's radius (2, "
        "the pole's diameter)");
    s.height = 0;
    require_input_error([&] { facet::make_primitive(s); },
                        "height must be finite and greater than 0");

    s = facet::PrimitiveSpec{};
    s.type = "platform";
    s.size = 1;
    s.hole_radius = 0.5f;
    require_input_error([&] { facet::make_primitive(s); },
                        "primitive 'platform': hole_radius (0.5) must be less than size / 2 (0.5)");
    s.hole_radius = 0;
    require_input_error([&] { facet::make_primitive(s); },
                        "hole_radius must be finite and greater than 0, got 0");
    s.hole_radius = 0.1f;
    s.thickness = -1;
    require_input_error([&] { facet::make_primitive(s); },
                        "thickness must be finite and greater than 0, got -1");
    s.thickness = INFINITY;
    require_input_error([&] { facet::make_primitive(s); }, "thickness must be finite");
    s.thickness = 0.1f;
    s.segments = 2;
    require_input_error([&] { facet::make_primitive(s); }, "segments must be between 3 and 65536");
    // The defaults build.
    CHECK_NOTHROW(facet::make_primitive(facet::PrimitiveSpec{"platform"}));
    facet::PrimitiveSpec pole_spec{"flagpole"};
    pole_spec.radius = 0.05f;  // the scene's default for a flagpole
    CHECK_NOTHROW(facet::make_primitive(pole_spec));
}

TEST_CASE("the shipped flag scene's pole fits its platform's hole exactly", "[primitives][flag]") {
    // Seed 004: the hole's radius is the pole's, and the pole's foot is the
    // centre of the platform's bottom face. Same radius and segments make
    // every corner of the hole's rim a corner of the pole's side: no gap.
    const facet::SceneDesc scene = facet::test::load(facet::test::source_path("scenes/flag.yaml"));
    const facet::ObjectDesc* pole_obj = nullptr;
    const facet::ObjectDesc* slab_obj = nullptr;
    for (const auto& o : scene.objects) {
        if (o.name == "pole") pole_obj = &o;
        if (o.name == "platform") slab_obj = &o;
    }
    REQUIRE(pole_obj);
    REQUIRE(slab_obj);
    const facet::PrimitiveSpec& ps = pole_obj->primitive->spec;
    const facet::PrimitiveSpec& ss = slab_obj->primitive->spec;
    CHECK(ss.hole_radius == ps.radius);
    CHECK(ss.segments == ps.segments);
    const float pole_foot = pole_obj->translate.value.y - ps.height / 2;
    const float slab_bottom = slab_obj->translate.value.y - ss.thickness / 2;
    CHECK(pole_foot == Approx(slab_bottom).margin(1e-6));

    const facet::Mesh pole_mesh = facet::make_primitive(ps), slab_mesh = facet::make_primitive(ss);
    size_t rim = 0;
    for (const glm::vec3& q : slab_mesh.parts[0].positions) {
        if (std::sqrt(q.x * q.x + q.z * q.z) > ss.hole_radius * 1.00001f) continue;
        bool on_pole = false;
        for (const glm::vec3& p : pole_mesh.parts[0].positions)
            on_pole = on_pole || (p.x == q.x && p.z == q.z);
        CHECK(on_pole);
        ++rim;
    }
    CHECK(rim >= 2 * static_cast<size_t>(ss.segments));
}
