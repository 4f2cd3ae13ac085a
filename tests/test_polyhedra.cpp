// The faceted and round procedural solids (src/shapes/polyhedra.cpp and
// primitives.cpp): the vertex, edge and face counts of the polyhedron each
// one is, Euler characteristics, closed outward surfaces, flat or smooth
// normals, sizes; and their scene keys, with the errors for bad values.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "asset_support.hpp"
#include "core/error.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "shapes/primitives.hpp"
#include "support.hpp"

using facet::test::centroid;
using facet::test::corner;
using facet::test::face_cross;
using facet::test::require_bounds;
using facet::test::require_closed_and_oriented;
using facet::test::require_normals_agree_with_winding;
using facet::test::surface_area;
using facet::test::TempDir;
using facet::test::Topology;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The polyhedron behind a triangle mesh: positions welded within `eps`,
// faces the groups of triangles joined across shared edges with the same
// normal (so fans of pentagons and the quads of a box count once), and
// edges only those between different faces. With `quads_by_construction`
// only the two triangles of a quad (triangles 2k and 2k + 1) are joined: a
// torus with an odd number of rings has a flat annulus at the bottom, made
// of quads that are coplanar but not one polygon.
struct Polyhedron {
    size_t vertices = 0, edges = 0, faces = 0;
    std::vector<size_t> face_triangles;  // triangles in each face
    std::vector<float> edge_lengths;
    long euler() const {
        return static_cast<long>(vertices) - static_cast<long>(edges) + static_cast<long>(faces);
    }
};

Polyhedron polyhedron_of(const facet::MeshPart& part, float eps = 1e-5f,
                         bool quads_by_construction = false) {
    std::vector<glm::vec3> welded;
    std::vector<size_t> id = facet::test::weld_positions(part, eps, welded);
    const size_t triangles = part.triangle_count();
    std::vector<glm::vec3> normal(triangles);
    std::map<std::pair<size_t, size_t>, std::vector<size_t>> edge_triangles;
    for (size_t t = 0; t < triangles; ++t) {
        normal[t] = glm::normalize(face_cross(part, t));
        for (int k = 0; k < 3; ++k) {
            size_t a = id[part.indices[3 * t + k]], b = id[part.indices[3 * t + (k + 1) % 3]];
            edge_triangles[std::minmax(a, b)].push_back(t);
        }
    }
    std::vector<size_t> group(triangles);
    std::iota(group.begin(), group.end(), size_t(0));
    auto root = [&](size_t t) {
        while (group[t] != t) t = group[t] = group[group[t]];
        return t;
    };
    for (const auto& [edge, tris] : edge_triangles)
        if (tris.size() == 2 && glm::dot(normal[tris[0]], normal[tris[1]]) > 1 - 1e-5f &&
            (!quads_by_construction || tris[0] / 2 == tris[1] / 2))
            group[root(tris[0])] = root(tris[1]);
    Polyhedron p;
    p.vertices = welded.size();
    std::map<size_t, size_t> sizes;
    for (size_t t = 0; t < triangles; ++t) ++sizes[root(t)];
    p.faces = sizes.size();
    for (const auto& [r, n] : sizes) p.face_triangles.push_back(n);
    for (const auto& [edge, tris] : edge_triangles)
        if (tris.size() != 2 || root(tris[0]) != root(tris[1])) {
            ++p.edges;
            p.edge_lengths.push_back(glm::length(welded[edge.first] - welded[edge.second]));
        }
    return p;
}

const facet::MeshPart& only_part(const facet::Mesh& mesh) {
    REQUIRE(mesh.parts.size() == 1);
    return mesh.parts[0];
}

facet::Mesh make(const std::string& type, float radius = 0.5f) {
    facet::PrimitiveSpec s;
    s.type = type;
    s.radius = radius;
    return facet::make_primitive(s);
}

// Unit normals, one UV per vertex inside [0, 1] (u up to `max_u` for shapes
// whose UVs wrap round), no zero-area triangles.
void check_attributes(const facet::MeshPart& part, float max_u = 1.0f) {
    REQUIRE(part.normals.size() == part.positions.size());
    REQUIRE(part.uvs.size() == part.positions.size());
    for (uint32_t i : part.indices) REQUIRE(i < part.positions.size());
    for (const auto& n : part.normals) CHECK(glm::length(n) == Approx(1.0f).margin(1e-5));
    for (const auto& uv : part.uvs) {
        CHECK(uv.x >= 0.0f);
        CHECK(uv.x <= max_u);
        CHECK(uv.y >= 0.0f);
        CHECK(uv.y <= 1.0f);
    }
    for (size_t t = 0; t < part.triangle_count(); ++t) CHECK(glm::length(face_cross(part, t)) > 0);
}

// Every triangle of a solid convex around the origin faces away from it.
void check_outward(const facet::MeshPart& part) {
    for (size_t t = 0; t < part.triangle_count(); ++t)
        CHECK(glm::dot(face_cross(part, t), centroid(part, t)) > 0);
}

// Flat: every corner's normal is its triangle's own (so vertices are split per face).
void check_flat(const facet::MeshPart& part) {
    for (size_t t = 0; t < part.triangle_count(); ++t) {
        glm::vec3 f = glm::normalize(face_cross(part, t));
        for (int k = 0; k < 3; ++k) {
            INFO("triangle " << t << " corner " << k);
            CHECK(glm::dot(part.normals[part.indices[3 * t + k]], f) > 1 - 1e-5f);
        }
    }
}

// Closed and oriented (shared helper), with the counts of the polyhedron.
Polyhedron check_closed_polyhedron(const facet::Mesh& mesh, size_t v, size_t e, size_t f,
                                   long euler = 2, float eps = 1e-5f,
                                   bool quads_by_construction = false) {
    Topology topo = require_closed_and_oriented(mesh, eps);
    Polyhedron p = polyhedron_of(only_part(mesh), eps, quads_by_construction);
    CHECK(topo.vertices == v);
    CHECK(p.vertices == v);
    CHECK(p.edges == e);
    CHECK(p.faces == f);
    CHECK(p.euler() == euler);
    CHECK(topo.vertices - topo.edges + topo.faces == static_cast<size_t>(euler));
    return p;
}

struct Solid {
    const char* type;
    size_t v, e, f, sides;  // sides of each face
    double edge;            // edge length over circumradius
};

}  // namespace

TEST_CASE("Platonic solids: counts, regular faces, corners on the circumsphere",
          "[assets][primitives][polyhedra]") {
    const double phi = (1 + std::sqrt(5.0)) / 2;
    for (const Solid s : {Solid{"tetrahedron", 4, 6, 4, 3, std::sqrt(8.0 / 3.0)},
                          Solid{"octahedron", 6, 12, 8, 3, std::sqrt(2.0)},
                          Solid{"icosahedron", 12, 30, 20, 3, 1 / std::sin(2 * kPi / 5)},
                          Solid{"dodecahedron", 20, 30, 12, 5, 4 / (std::sqrt(3.0) * 2 * phi)}})
        for (float radius : {0.5f, 2.0f}) {
            DYNAMIC_SECTION(s.type << " radius " << radius) {
                facet::Mesh mesh = make(s.type, radius);
                const auto& part = only_part(mesh);
                check_attributes(part);
                check_outward(part);
                check_flat(part);
                CHECK(mesh.triangle_count() == s.f * (s.sides - 2));  // fans
                Polyhedron p = check_closed_polyhedron(mesh, s.v, s.e, s.f, 2, 1e-5f * radius);
                for (size_t n : p.face_triangles) CHECK(n == s.sides - 2);
                for (float len : p.edge_lengths)
                    CHECK(len == Approx(s.edge * radius).epsilon(1e-5));
                for (const auto& pos : part.positions)
                    CHECK(glm::length(pos) == Approx(radius).epsilon(1e-5));
                // +Y up: each has a vertex or, for the dodecahedron, a face on top.
                CHECK(mesh.bounds().max.y ==
                      Approx(s.sides == 5 ? 0.7947 * radius : radius).epsilon(1e-3));
            }
        }
    SECTION("cube keeps its edge length as size") {
        facet::PrimitiveSpec s;
        s.type = "cube";
        s.size = 2;
        facet::Mesh mesh = facet::make_primitive(s);
        check_flat(only_part(mesh));
        Polyhedron p = check_closed_polyhedron(mesh, 8, 12, 6);
        for (float len : p.edge_lengths) CHECK(len == Approx(2.0f));
        for (const auto& pos : only_part(mesh).positions)
            CHECK(glm::length(pos) == Approx(std::sqrt(3.0f)));
    }
}

TEST_CASE("box has the three given sizes", "[assets][primitives][polyhedra]") {
    for (glm::vec3 size : {glm::vec3(1, 2, 3), glm::vec3(0.5f, 0.25f, 4), glm::vec3(1)}) {
        DYNAMIC_SECTION("size " << size.x << " " << size.y << " " << size.z) {
            facet::PrimitiveSpec s;
            s.type = "box";
            s.box_size = size;
            facet::Mesh mesh = facet::make_primitive(s);
            const auto& part = only_part(mesh);
            check_attributes(part);
            check_outward(part);
            check_flat(part);
            CHECK(mesh.triangle_count() == 12);
            Polyhedron p = check_closed_polyhedron(mesh, 8, 12, 6);
            for (size_t n : p.face_triangles) CHECK(n == 2);
            require_bounds(mesh, -size / 2.0f, size / 2.0f);
            CHECK(surface_area(part) ==
                  Approx(2.0 * (size.x * size.y + size.y * size.z + size.z * size.x)));
            // Twelve edges, four along each axis with that axis's size.
            std::vector<float> lengths = p.edge_lengths, want;
            for (int k = 0; k < 3; ++k) want.insert(want.end(), 4, size[k]);
            std::sort(lengths.begin(), lengths.end());
            std::sort(want.begin(), want.end());
            REQUIRE(lengths.size() == want.size());
            for (size_t i = 0; i < want.size(); ++i) CHECK(lengths[i] == Approx(want[i]));
        }
    }
}

namespace {

// A prism, antiprism or pyramid of `sides` sides, with a top radius when given.
facet::PrimitiveSpec polygon_solid(const std::string& type, int sides, float radius, float height,
                                   std::optional<float> top_radius = std::nullopt) {
    facet::PrimitiveSpec s;
    s.type = type;
    s.sides = sides;
    s.radius = radius;
    s.height = height;
    s.top_radius = top_radius;
    return s;
}

}  // namespace

TEST_CASE("prism, antiprism and pyramid over n sides", "[assets][primitives][polyhedra]") {
    const float radius = 0.8f, height = 1.5f;
    for (int n : {3, 4, 5, 12}) {
        const size_t sides = static_cast<size_t>(n);
        for (const std::string type : {"prism", "antiprism", "pyramid"}) {
            DYNAMIC_SECTION(type << " " << n) {
                facet::Mesh mesh = facet::make_primitive(polygon_solid(type, n, radius, height));
                const auto& part = only_part(mesh);
                // The antiprism's band of triangles reaches half a step past u = 1.
                check_attributes(part, type == "antiprism" ? 1.0f + 0.5f / n : 1.0f);
                check_outward(part);
                check_flat(part);
                Polyhedron p;
                if (type == "prism")
                    p = check_closed_polyhedron(mesh, 2 * sides, 3 * sides, sides + 2);
                else if (type == "antiprism")
                    p = check_closed_polyhedron(mesh, 2 * sides, 4 * sides, 2 * sides + 2);
                else
                    p = check_closed_polyhedron(mesh, sides + 1, 2 * sides, sides + 1);
                // The n-gon caps are fans of n - 2 triangles.
                CHECK(std::count(p.face_triangles.begin(), p.face_triangles.end(), sides - 2) >=
                      (type == "pyramid" ? 1 : 2));
                facet::Bounds b = mesh.bounds();
                CHECK(b.min.y == Approx(-height / 2));
                CHECK(b.max.y == Approx(height / 2));
                for (const auto& pos : part.positions) {
                    float r = glm::length(glm::vec2(pos.x, pos.z));
                    if (type == "pyramid" && pos.y > 0)
                        CHECK(r == Approx(0.0f).margin(1e-6));  // the apex
                    else
                        CHECK(r == Approx(radius));
                }
                // The base polygon's edges all have the side length of a regular n-gon.
                double side = 2 * radius * std::sin(kPi / n);
                size_t base_edges = 0;
                for (float len : p.edge_lengths)
                    if (std::abs(len - side) < 1e-5) ++base_edges;
                CHECK(base_edges >= sides);
            }
        }
    }
}

TEST_CASE("icosphere subdivides the icosahedron onto the sphere",
          "[assets][primitives][polyhedra]") {
    for (int level : {0, 1, 2, 3}) {
        DYNAMIC_SECTION("subdivisions " << level) {
            facet::PrimitiveSpec s;
            s.type = "icosphere";
            s.radius = 1.5f;
            s.subdivisions = level;
            facet::Mesh mesh = facet::make_primitive(s);
            const auto& part = only_part(mesh);
            const size_t scale = size_t(1) << (2 * level);  // 4^level
            CHECK(mesh.triangle_count() == 20 * scale);
            check_attributes(part, 1.25f);
            check_outward(part);
            require_normals_agree_with_winding(part);
            check_closed_polyhedron(mesh, 10 * scale + 2, 30 * scale, 20 * scale, 2, 1e-5f);
            for (size_t i = 0; i < part.positions.size(); ++i) {
                CHECK(glm::length(part.positions[i]) == Approx(1.5f).epsilon(1e-5));
                // Smooth: the normal is the radial direction.
                CHECK(glm::dot(part.normals[i], glm::normalize(part.positions[i])) > 1 - 1e-5f);
            }
            // Faceted on request, with the same polyhedron.
            s.smooth = false;
            facet::Mesh flat = facet::make_primitive(s);
            check_flat(only_part(flat));
            check_outward(only_part(flat));
            check_closed_polyhedron(flat, 10 * scale + 2, 30 * scale, 20 * scale, 2, 1e-5f);
        }
    }
    SECTION("the finest level approaches the sphere") {
        facet::PrimitiveSpec s;
        s.type = "icosphere";
        s.radius = 1;
        s.subdivisions = facet::kMaxIcosphereSubdivisions;
        facet::Mesh mesh = facet::make_primitive(s);
        CHECK(mesh.triangle_count() == 20u * 16384u);
        CHECK(surface_area(only_part(mesh)) == Approx(4 * kPi).epsilon(1e-4));
    }
}

TEST_CASE("torus: a ring round +Y with Euler characteristic 0", "[assets][primitives][polyhedra]") {
    struct Case {
        int segments, rings;
        float radius, tube;
    };
    for (const Case c : {Case{3, 3, 1.0f, 0.25f}, Case{24, 12, 0.5f, 0.2f}, Case{7, 5, 2.0f, 1.9f},
                         Case{8, 6, 1.0f, 0.3f}}) {
        DYNAMIC_SECTION(c.segments << "x" << c.rings << " radius " << c.radius << " tube "
                                   << c.tube) {
            facet::PrimitiveSpec s;
            s.type = "torus";
            s.segments = c.segments;
            s.rings = c.rings;
            s.radius = c.radius;
            s.tube = c.tube;
            facet::Mesh mesh = facet::make_primitive(s);
            const auto& part = only_part(mesh);
            check_attributes(part);
            require_normals_agree_with_winding(part);
            const size_t quads = static_cast<size_t>(c.segments * c.rings);
            CHECK(mesh.triangle_count() == 2 * quads);
            Polyhedron p = check_closed_polyhedron(mesh, quads, 2 * quads, quads, 0, 1e-5f, true);
            for (size_t n : p.face_triangles) CHECK(n == 2);  // planar quads
            if (c.rings % 2 == 0) {  // no two quads coplanar: the same counts from the geometry
                Polyhedron g = check_closed_polyhedron(mesh, quads, 2 * quads, quads, 0, 1e-5f);
                for (size_t n : g.face_triangles) CHECK(n == 2);
            }
            // The centre circle of the tube (through the vertices), and that
            // of the faceted tube (through the quads' centres).
            auto axis_point = [&](glm::vec3 q, float scale = 1) {
                return scale * c.radius * glm::normalize(glm::vec3(q.x, 0, q.z));
            };
            const float chord = static_cast<float>(std::cos(kPi / c.segments));
            for (size_t t = 0; t < part.triangle_count(); ++t) {  // outward from the tube
                const size_t q = t - t % 2;  // the quad's triangles (a, b, c) and (a, c, d)
                glm::vec3 m = (corner(part, q, 0) + corner(part, q, 1) + corner(part, q, 2) +
                               corner(part, q + 1, 2)) /
                              4.0f;
                CHECK(glm::dot(face_cross(part, t), m - axis_point(m, chord)) > 0);
            }
            for (size_t i = 0; i < part.positions.size(); ++i) {
                glm::vec3 q = part.positions[i], from_axis = q - axis_point(q);
                CHECK(glm::length(from_axis) == Approx(c.tube).epsilon(1e-4));
                CHECK(glm::dot(part.normals[i], glm::normalize(from_axis)) > 1 - 1e-4f);
            }
            // The tube's first ring is its top circle; the bottom one only with an even count.
            facet::Bounds b = mesh.bounds();
            CHECK(b.max.y == Approx(c.tube).epsilon(1e-5));
            CHECK(b.min.y >= -c.tube * (1 + 1e-5f));
            if (c.rings % 2 == 0) CHECK(b.min.y == Approx(-c.tube).epsilon(1e-5));
        }
    }
}

TEST_CASE("smooth: false facets the round primitives", "[assets][primitives][polyhedra]") {
    for (const std::string type : {"sphere", "cylinder", "cone", "torus", "icosphere"}) {
        DYNAMIC_SECTION(type) {
            facet::PrimitiveSpec s;
            s.type = type;
            s.segments = 12;
            s.rings = 6;
            facet::Mesh smooth = facet::make_primitive(s);
            // Smooth by default: some corner's normal is not its triangle's.
            const auto& sp = only_part(smooth);
            bool bent = false;
            for (size_t t = 0; t < sp.triangle_count(); ++t)
                for (int k = 0; k < 3; ++k)
                    bent = bent || glm::dot(sp.normals[sp.indices[3 * t + k]],
                                            glm::normalize(face_cross(sp, t))) < 0.999f;
            CHECK(bent);
            s.smooth = false;
            facet::Mesh flat = facet::make_primitive(s);
            check_attributes(only_part(flat), 1.25f);
            check_flat(only_part(flat));
            CHECK(flat.triangle_count() == smooth.triangle_count());
            Topology a = require_closed_and_oriented(smooth), b = require_closed_and_oriented(flat);
            CHECK(a.vertices == b.vertices);
            CHECK(a.edges == b.edges);
        }
    }
}

TEST_CASE("bad polyhedron parameters name the parameter and its range",
          "[assets][primitives][polyhedra]") {
    struct Case {
        const char* type;
        void (*set)(facet::PrimitiveSpec&);
        const char* says;
    };
    for (const Case c : {
             Case{"prism", [](facet::PrimitiveSpec& s) { s.sides = 2; }, "sides must be between 3"},
             Case{"pyramid", [](facet::PrimitiveSpec& s) { s.sides = -1; }, "sides"},
             Case{"icosphere", [](facet::PrimitiveSpec& s) { s.subdivisions = 8; },
                  "subdivisions must be between 0 and 7"},
             Case{"icosphere", [](facet::PrimitiveSpec& s) { s.subdivisions = -1; },
                  "between 0 and 7"},
             Case{"torus", [](facet::PrimitiveSpec& s) { s.tube = 0.5f; }, "less than radius"},
             Case{"torus", [](facet::PrimitiveSpec& s) { s.tube = 0; }, "tube must be finite"},
             Case{"torus", [](facet::PrimitiveSpec& s) { s.rings = 2; }, "rings must be between 3"},
             Case{"box", [](facet::PrimitiveSpec& s) { s.box_size.y = 0; }, "box size"},
             Case{"box", [](facet::PrimitiveSpec& s) { s.box_size.z = -1; }, "greater than 0"},
             Case{"dodecahedron", [](facet::PrimitiveSpec& s) { s.radius = 0; }, "radius"},
             Case{"antiprism", [](facet::PrimitiveSpec& s) { s.height = -2; }, "height"},
             Case{"cube", [](facet::PrimitiveSpec& s) { s.smooth = true; }, "smooth applies"},
         }) {
        DYNAMIC_SECTION(c.type << " " << c.says) {
            facet::PrimitiveSpec s;
            s.type = c.type;
            c.set(s);
            facet::test::require_input_error([&] { facet::make_primitive(s); }, c.says);
        }
    }
}

// --- Scene files ---------------------------------------------------------------

namespace {

std::string scene_with(const std::string& primitive) {
    return "objects:\n  - primitive: " + primitive + "\n";
}

}  // namespace

TEST_CASE("frustums: prism and pyramid with a top radius (seed 001)",
          "[assets][primitives][polyhedra]") {
    const float bottom = 1.0f, top = 0.4f, height = 2.0f;
    for (int n : {3, 4, 7}) {
        const size_t sides = static_cast<size_t>(n);
        for (const std::string type : {"prism", "pyramid"}) {
            DYNAMIC_SECTION(type << " " << n) {
                facet::Mesh mesh =
                    facet::make_primitive(polygon_solid(type, n, bottom, height, top));
                const auto& part = only_part(mesh);
                check_outward(part);
                check_flat(part);  // the trapezoid sides are planar
                // A truncated n-gonal pyramid: V = 2n, E = 3n, F = n + 2, so V - E + F = 2.
                const Polyhedron p = check_closed_polyhedron(mesh, 2 * sides, 3 * sides, sides + 2);
                CHECK(std::count(p.face_triangles.begin(), p.face_triangles.end(), sides - 2) >= 2);
                for (const auto& pos : part.positions) {
                    const float r = glm::length(glm::vec2(pos.x, pos.z));
                    CHECK(r == Approx(pos.y > 0 ? top : bottom));
                }
            }
        }
    }
}

TEST_CASE("prisms and pyramids by base edge length and top radius from a scene",
          "[scene][polyhedra]") {
    TempDir dir("polyhedra");
    const std::string path = facet::test::write_text(dir.file("s.yaml"), R"(objects:
  - primitive: { type: prism, sides: 6, edge: 0.5, height: 1 }
  - primitive: { type: pyramid, sides: 4, edge: 2, top_radius: 0.5, height: 1 }
  - primitive: { type: pyramid, sides: 3, edge: 1, height: 1 }
)");
    const facet::SceneDesc scene = facet::test::load(path);
    // A hexagon's circumradius is its edge; a square's is edge / sqrt 2.
    CHECK(scene.objects[0].primitive->spec.radius == Approx(0.5f));
    CHECK(scene.objects[1].primitive->spec.radius == Approx(2 / std::sqrt(2.0f)));
    CHECK(*scene.objects[1].primitive->spec.top_radius == 0.5f);
    CHECK(scene.objects[2].primitive->spec.radius == Approx(1 / std::sqrt(3.0f)));
    const facet::World world = facet::build_world(scene);
    CHECK(world.draws[1].triangle_count == 2 * 4 + 2 * 2);  // four trapezoids, two square caps
    CHECK(world.draws[2].triangle_count == 3 + 1);          // an apex: no top cap

    for (const auto& [primitive, key, says] : std::vector<std::array<std::string, 3>>{
             {"{ type: prism, radius: 1, edge: 1 }", "objects.0.primitive.edge",
              "either 'radius' or 'edge'"},
             {"{ type: cube, top_radius: 1 }", "objects.0.primitive.top_radius",
              "does not apply to a cube"},
             {"{ type: antiprism, top_radius: 1 }", "objects.0.primitive.top_radius",
              "does not apply to a antiprism"},
             {"{ type: prism, top_radius: 0 }", "objects.0.primitive.top_radius", "top_radius"},
             {"{ type: pyramid, top_radius: -1 }", "objects.0.primitive.top_radius",
              "between 0"}}) {
        INFO(primitive);
        const std::string bad = facet::test::write_text(
            dir.file("bad.yaml"), "objects:\n  - primitive: " + primitive + "\n");
        try {
            facet::build_world(facet::test::load(bad));
            FAIL("expected an error");
        } catch (const facet::Error& e) {
            CHECK(e.code() == facet::ExitCode::invalid_input);
            CHECK_THAT(e.what(), Catch::Contains(says));
        }
    }
}

TEST_CASE("scene keys of the new primitives reach the meshes", "[scene][polyhedra]") {
    TempDir dir("polyhedra");
    std::string path = facet::test::write_text(dir.file("s.yaml"), R"(objects:
  - primitive: { type: box, size: [1, 2, 3] }
  - primitive: { type: box, size: 0.5 }
  - primitive: { type: prism, sides: 5, radius: 1, height: 2 }
  - primitive: { type: icosphere, subdivisions: 1, smooth: false }
  - primitive: { type: torus, radius: 2, segments: 8, rings: 4 }
  - primitive: dodecahedron
)");
    facet::SceneDesc scene = facet::test::load(path);
    REQUIRE(scene.objects.size() == 6);
    const auto& box = scene.objects[0].primitive->spec;
    CHECK(box.box_size == glm::vec3(1, 2, 3));
    CHECK(scene.objects[1].primitive->spec.box_size == glm::vec3(0.5f));
    CHECK(scene.objects[2].primitive->spec.sides == 5);
    CHECK(scene.objects[3].primitive->spec.subdivisions == 1);
    CHECK(scene.objects[3].primitive->spec.smooth == false);
    CHECK(scene.objects[4].primitive->spec.tube == 1.0f);  // half the radius by default
    CHECK(scene.objects[5].primitive->spec.type == "dodecahedron");

    facet::World world = facet::build_world(scene);
    REQUIRE(world.draws.size() == 6);
    CHECK(world.draws[0].triangle_count == 12);
    CHECK(world.draws[2].triangle_count == 2 * 5 + 2 * 3);  // quads and two pentagon fans
    CHECK(world.draws[3].triangle_count == 80);
    CHECK(world.draws[4].triangle_count == 2 * 8 * 4);
    CHECK(world.draws[5].triangle_count == 12 * 3);
    facet::Bounds b = world.object_bounds[0];
    CHECK(b.max.x - b.min.x == Approx(1.0f));
    CHECK(b.max.y - b.min.y == Approx(2.0f));
    CHECK(b.max.z - b.min.z == Approx(3.0f));
    facet::Bounds t = world.object_bounds[4];
    CHECK(t.max.z == Approx(3.0f));
    CHECK(t.max.y == Approx(1.0f));
}

TEST_CASE("bad primitive values in a scene name the key and the range", "[scene][polyhedra]") {
    struct Case {
        std::string primitive, key, says;
    };
    const std::string sphere_keys = "type, radius, segments, rings, smooth";
    for (const Case& c : std::vector<Case>{
             {"{ type: prism, sides: 2 }", "objects.0.primitive.sides",
              "between 3 and 4096, got 2"},
             {"{ type: pyramid, sides: 3.5 }", "objects.0.primitive.sides", "whole number"},
             {"{ type: antiprism, sides: 5000 }", "objects.0.primitive.sides",
              "between 3 and 4096"},
             {"{ type: sphere, sides: 5 }", "objects.0.primitive.sides",
              "does not apply to a sphere (its keys are: " + sphere_keys + ")"},
             {"{ type: cube, radius: 1 }", "objects.0.primitive.radius", "type, size"},
             {"{ type: box, smooth: true }", "objects.0.primitive.smooth", "does not apply"},
             {"{ type: icosahedron, radius: 0 }", "objects.0.primitive.radius",
              "between 1e-06 and 1e+07, got 0"},
             {"{ type: dodecahedron, radius: -1 }", "objects.0.primitive.radius", "between 1e-06"},
             {"{ type: pyramid, height: 0 }", "objects.0.primitive.height", "between 1e-06"},
             {"{ type: icosphere, subdivisions: 8 }", "objects.0.primitive.subdivisions",
              "between 0 and 7, got 8"},
             {"{ type: icosphere, subdivisions: -1 }", "objects.0.primitive.subdivisions",
              "between 0 and 7"},
             {"{ type: icosphere, smooth: maybe }", "objects.0.primitive.smooth", "true or false"},
             {"{ type: torus, segments: 0 }", "objects.0.primitive.segments", "between 3 and 4096"},
             {"{ type: torus, rings: 2 }", "objects.0.primitive.rings", "between 3 and 4096"},
             {"{ type: torus, radius: 0.5, tube: 0.6 }", "objects.0.primitive.tube",
              "less than the radius (0.5)"},
             {"{ type: torus, tube: -0.1 }", "objects.0.primitive.tube", "between 1e-06"},
             {"{ type: box, size: [1, 0, 2] }", "objects.0.primitive.size.1", "between 1e-06"},
             {"{ type: box, size: [1, 2] }", "objects.0.primitive.size", "3 numbers"},
             {"{ type: box, size: -2 }", "objects.0.primitive.size", "between 1e-06"},
             {"{ type: hexahedron }", "objects.0.primitive.type", "icosphere, torus"},
             {"octahedra", "objects.0.primitive", "must be one of"},
         }) {
        DYNAMIC_SECTION(c.primitive) {
            TempDir dir("polyhedra-error");
            std::string path =
                facet::test::write_text(dir.file("bad.yaml"), scene_with(c.primitive));
            try {
                facet::load_scene(path, facet::test::with_styles());
                FAIL("accepted " << c.primitive);
            } catch (const facet::Error& e) {
                CHECK(e.code() == facet::ExitCode::invalid_input);
                CHECK(static_cast<int>(e.code()) == 2);
                CHECK_THAT(e.what(), Catch::Contains("'" + c.key + "'"));
                CHECK_THAT(e.what(), Catch::Contains(c.says));
                CHECK_THAT(e.what(), Catch::Contains(path));
            }
        }
    }
}
