// Wavefront OBJ loading (src/assets/obj_loader.cpp), geometry: polygons
// triangulated the right way round, indices, made-up normals, texture
// coordinates and text encodings. The files are small ones with known
// answers, written here.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"

using namespace facet::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string unit_cube_obj_without_normals() {
    // Eight corners of [-1,1]^3; faces counter-clockwise seen from outside.
    return "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
           "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
           "f 5 6 7 8\nf 2 1 4 3\nf 6 2 3 7\nf 1 5 8 4\nf 8 7 3 4\nf 1 2 6 5\n";
}

// A UV sphere with shared vertices (one vertex at each pole), no normals.
std::string sphere_obj(int segments, int rings, float radius) {
    std::ostringstream o;
    o << "v 0 " << radius << " 0\n";
    for (int r = 1; r < rings; ++r) {
        double theta = kPi * r / rings;
        for (int s = 0; s < segments; ++s) {
            double phi = 2 * kPi * s / segments;
            o << "v " << radius * std::sin(theta) * std::sin(phi) << ' ' << radius * std::cos(theta)
              << ' ' << radius * std::sin(theta) * std::cos(phi) << '\n';
        }
    }
    o << "v 0 " << -radius << " 0\n";
    auto at = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };  // 1-based
    const int south = 2 + (rings - 1) * segments;
    for (int s = 0; s < segments; ++s) o << "f 1 " << at(1, s) << ' ' << at(1, s + 1) << '\n';
    for (int r = 1; r < rings - 1; ++r)
        for (int s = 0; s < segments; ++s)
            o << "f " << at(r, s) << ' ' << at(r + 1, s) << ' ' << at(r + 1, s + 1) << ' '
              << at(r, s + 1) << '\n';
    for (int s = 0; s < segments; ++s)
        o << "f " << at(rings - 1, s) << ' ' << south << ' ' << at(rings - 1, s + 1) << '\n';
    return o.str();
}

// Planar polygon as OBJ: one face through all points in order.
std::string polygon_obj(const std::vector<glm::vec3>& points) {
    std::ostringstream o;
    for (const auto& p : points) o << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    o << 'f';
    for (size_t i = 0; i < points.size(); ++i) o << ' ' << i + 1;
    o << '\n';
    return o.str();
}

// Point in polygon, even-odd rule, in the plane spanned by axes u, v.
bool inside_polygon(const std::vector<glm::vec3>& pts, glm::vec3 q, glm::vec3 u, glm::vec3 v) {
    bool in = false;
    float qx = glm::dot(q, u), qy = glm::dot(q, v);
    for (size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
        float xi = glm::dot(pts[i], u), yi = glm::dot(pts[i], v);
        float xj = glm::dot(pts[j], u), yj = glm::dot(pts[j], v);
        if ((yi > qy) != (yj > qy) && qx < (xj - xi) * (qy - yi) / (yj - yi) + xi) in = !in;
    }
    return in;
}

// A correct triangulation of a simple polygon: n - 2 triangles, all facing the
// polygon's way, each inside it, and together exactly its area.
void require_triangulates(const std::vector<glm::vec3>& pts) {
    TempDir dir("obj-poly");
    std::string path = write_text(dir.file("poly.obj"), polygon_obj(pts));
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    REQUIRE(mesh.triangle_count() == pts.size() - 2);
    glm::vec3 area_vec = polygon_area_vector(pts);
    float area = glm::length(area_vec);
    glm::vec3 n = area_vec / area;
    glm::vec3 u = glm::normalize(pts[1] - pts[0]);
    u = glm::normalize(u - n * glm::dot(u, n));
    glm::vec3 v = glm::cross(n, u);
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            glm::vec3 c = face_cross(part, t);
            INFO("triangle " << t);
            CHECK(glm::dot(c, n) > 0);
            CHECK(inside_polygon(pts, centroid(part, t), u, v));
            for (int k = 0; k < 3; ++k)
                CHECK(glm::dot(part.normals[part.indices[3 * t + k]], n) ==
                      Approx(1.0f).margin(1e-4));
        }
    CHECK(total_area(mesh) == Approx(area).epsilon(1e-4));
}

std::vector<glm::vec3> embed(const std::vector<glm::vec2>& pts2, glm::vec3 origin, glm::vec3 u,
                             glm::vec3 v) {
    std::vector<glm::vec3> out;
    for (auto p : pts2) out.push_back(origin + p.x * u + p.y * v);
    return out;
}

// n points evenly round the unit circle, counter-clockwise from +x.
std::vector<glm::vec2> unit_circle(int n) {
    std::vector<glm::vec2> ring;
    for (int i = 0; i < n; ++i)
        ring.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)});
    return ring;
}

}  // namespace

// --- Polygons ---------------------------------------------------------------

TEST_CASE("OBJ quad becomes two counter-clockwise triangles", "[assets][obj]") {
    TempDir dir("obj");
    std::string path =
        write_text(dir.file("quad.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 1);
    const auto& part = mesh.parts[0];
    CHECK(part.triangle_count() == 2);
    CHECK(part.positions.size() == 4);  // the diagonal's ends are shared
    for (size_t t = 0; t < 2; ++t) {
        glm::vec3 c = face_cross(part, t);
        CHECK(c.z == Approx(1.0f));  // area 1/2 each, facing +Z like the quad
        CHECK(c.x == Approx(0.0f).margin(1e-6));
        CHECK(c.y == Approx(0.0f).margin(1e-6));
    }
    for (const auto& n : part.normals) CHECK(n.z == Approx(1.0f));
    CHECK(total_area(mesh) == Approx(1.0f));
    require_bounds(mesh, {0, 0, 0}, {1, 1, 0});
    CHECK(mesh.source == path);
    CHECK(part.uvs.empty());  // no vt in the file
}

TEST_CASE("OBJ convex quads split along their shorter diagonal", "[assets][obj]") {
    TempDir dir("obj");
    // A kite: diagonal 0-2 is 4 long, diagonal 1-3 is 2 long.
    std::string path =
        write_text(dir.file("kite.obj"), "v 0 0 0\nv 2 -1 0\nv 4 0 0\nv 2 1 0\nf 1 2 3 4\n");
    facet::Mesh mesh = facet::load_obj(path);
    REQUIRE(mesh.triangle_count() == 2);
    const auto& part = mesh.parts[0];
    for (size_t t = 0; t < 2; ++t) {
        bool has1 = false, has3 = false;
        for (int k = 0; k < 3; ++k) {
            has1 = has1 || corner(part, t, k) == glm::vec3(2, -1, 0);
            has3 = has3 || corner(part, t, k) == glm::vec3(2, 1, 0);
        }
        CHECK(has1);  // both triangles share the short diagonal's ends
        CHECK(has3);
        CHECK(face_cross(part, t).z > 0);
    }
}

TEST_CASE("OBJ convex polygons with five or more corners are fan-complete", "[assets][obj]") {
    for (int n : {5, 6, 8, 12, 40}) {
        DYNAMIC_SECTION(n << " corners") {
            // Far from the origin and in a tilted plane, so no axis or origin is special.
            require_triangulates(embed(unit_circle(n), {10, -7, 3},
                                       glm::normalize(glm::vec3(1, 1, 0)),
                                       glm::normalize(glm::vec3(-1, 1, 1))));
        }
    }
}

TEST_CASE("OBJ concave polygons are triangulated inside their outline", "[assets][obj]") {
    const std::vector<glm::vec2> ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    SECTION("dart-shaped quad whose shorter diagonal lies outside it") {
        require_triangulates(
            embed({{0, 0}, {1, 0.5f}, {2, 0}, {1, 5}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    }
    SECTION("L shape in the XY plane") {
        require_triangulates(embed(ell, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    }
    SECTION("L shape far from the origin") {
        require_triangulates(embed(ell, {5, 5, 0}, {1, 0, 0}, {0, 1, 0}));
    }
    SECTION("L shape with the origin inside the notch") {
        require_triangulates(
            embed({{-1, -1}, {1, -1}, {1, -0.5f}, {-0.5f, -0.5f}, {-0.5f, 1}, {-1, 1}}, {0, 0, 0},
                  {1, 0, 0}, {0, 1, 0}));
    }
    SECTION("five-pointed star, tilted") {
        std::vector<glm::vec2> star;
        for (int i = 0; i < 10; ++i) {
            double r = i % 2 ? 0.4 : 1.0, a = kPi / 2 + kPi * i / 5;
            star.push_back(
                {static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a))});
        }
        require_triangulates(
            embed(star, {3, 1, -2}, glm::normalize(glm::vec3(0, 1, 1)), {1, 0, 0}));
    }
    SECTION("comb with deep teeth in the YZ plane") {
        std::vector<glm::vec2> comb = {{0, 0}, {7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1},
                                       {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3},
                                       {2, 1}, {1, 1}, {1, 3}, {0, 3}};
        require_triangulates(embed(comb, {-4, 2, 2}, {0, 1, 0}, {0, 0, 1}));
    }
}

TEST_CASE("OBJ faces with more than 255 corners", "[assets][obj]") {
    // tinyobjloader counts face corners in a byte; these faces must neither
    // wrap around nor shift the faces after them.
    const int n = 300;
    std::vector<glm::vec3> pts = embed(unit_circle(n), {0, 0, 2}, {1, 0, 0}, {0, 1, 0});
    std::string text = polygon_obj(pts);
    text += "v 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\nf -4 -3 -2 -1\n";  // and a unit quad after it
    TempDir dir("obj");
    SECTION("a convex 300-gon and a quad") {
        facet::Mesh mesh = facet::load_obj(write_text(dir.file("big.obj"), text));
        check_sane(mesh);
        CHECK(mesh.triangle_count() == static_cast<size_t>(n - 2 + 2));
        CHECK(total_area(mesh) ==
              Approx(glm::length(polygon_area_vector(pts)) + 1.0f).epsilon(1e-4));
        require_bounds(mesh, {-1, -1, 0}, {6, 1, 2}, 1e-4f);
    }
    SECTION("and a quad with a vertex that does not exist") {
        std::string path = write_text(dir.file("big_bad.obj"), text + "f 1 2 3 999\n");
        require_input_error([&] { facet::load_obj(path); }, "big_bad.obj");
    }
}

// --- Indices, normals and texture coordinates ------------------------------

TEST_CASE("OBJ negative indices count back from the latest vertex", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(dir.file("relative.obj"),
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                  "vn 0 0 1\n"
                                  "f -4/-4/-1 -3/-3/-1 -2/-2/-1 -1/-1/-1\n"
                                  "v 0 0 5\nv 1 0 5\nv 1 1 5\n"
                                  "f -3 -2 -1\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 3);
    size_t at_z5 = 0, at_z0 = 0;
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            float z = corner(part, t, 0).z;
            for (int k = 1; k < 3; ++k) REQUIRE(corner(part, t, k).z == z);
            (z == 5 ? at_z5 : at_z0) += 1;
            CHECK(face_cross(part, t).z > 0);
        }
    CHECK(at_z0 == 2);  // the quad, from the first four vertices
    CHECK(at_z5 == 1);  // the triangle, from the last three
    // vt -2 of the quad is (1, 1): v flips to 0.
    bool found = false;
    for (const auto& part : mesh.parts)
        for (size_t i = 0; i < part.positions.size(); ++i)
            if (part.positions[i] == glm::vec3(1, 1, 0) && !part.uvs.empty()) {
                CHECK(part.uvs[i].x == Approx(1.0f));
                CHECK(part.uvs[i].y == Approx(0.0f).margin(1e-6));
                found = true;
            }
    CHECK(found);
}

TEST_CASE("OBJ cube without normals gets sharp face normals", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(dir.file("cube.obj"), unit_cube_obj_without_normals());
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 12);
    CHECK(mesh.vertex_count() == 24);  // each corner split three ways by the crease
    require_bounds(mesh, {-1, -1, -1}, {1, 1, 1});
    require_closed_and_oriented(mesh);
    CHECK(total_area(mesh) == Approx(24.0f));
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            glm::vec3 f = glm::normalize(face_cross(part, t));
            CHECK(glm::dot(f, centroid(part, t)) > 0);  // faces point outward
            // Face normals of a cube are axis aligned.
            CHECK(std::abs(f.x) + std::abs(f.y) + std::abs(f.z) == Approx(1.0f));
            for (int k = 0; k < 3; ++k) {
                glm::vec3 n = part.normals[part.indices[3 * t + k]];
                CHECK(glm::dot(n, f) == Approx(1.0f).margin(1e-5));
            }
        }
}

TEST_CASE("OBJ finely tessellated sphere without normals gets smooth normals", "[assets][obj]") {
    TempDir dir("obj");
    const int segments = 48, rings = 24;
    std::string path = write_text(dir.file("sphere.obj"), sphere_obj(segments, rings, 2.0f));
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == static_cast<size_t>(2 * segments * (rings - 1)));
    // Smooth: no vertex was split, one normal per position of the file.
    CHECK(mesh.vertex_count() == static_cast<size_t>(segments * (rings - 1) + 2));
    require_closed_and_oriented(mesh);
    require_bounds(mesh, {-2, -2, -2}, {2, 2, 2}, 1e-3f);
    for (const auto& part : mesh.parts)
        for (size_t i = 0; i < part.positions.size(); ++i) {
            glm::vec3 radial = glm::normalize(part.positions[i]);
            INFO("vertex at " << part.positions[i].x << ", " << part.positions[i].y << ", "
                              << part.positions[i].z);
            CHECK(glm::dot(part.normals[i], radial) > 0.999f);
        }
}

TEST_CASE("OBJ texture v is flipped to facet's top-down convention", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(dir.file("uv.obj"),
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "vt 0.25 0.1\nvt 0.75 0.1\nvt 0.25 0.8\n"
                                  "f 1/1 2/2 3/3\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 1);
    const auto& part = mesh.parts[0];
    REQUIRE(part.uvs.size() == part.positions.size());
    std::map<std::pair<float, float>, glm::vec2> expected = {
        {{0, 0}, {0.25f, 0.9f}}, {{1, 0}, {0.75f, 0.9f}}, {{0, 1}, {0.25f, 0.2f}}};
    for (size_t i = 0; i < part.positions.size(); ++i) {
        glm::vec2 want = expected.at({part.positions[i].x, part.positions[i].y});
        CHECK(part.uvs[i].x == Approx(want.x));
        CHECK(part.uvs[i].y == Approx(want.y));
    }
}

TEST_CASE("OBJ vertices with different texture coordinates stay separate", "[assets][obj]") {
    // Two triangles share positions 1 and 3 but not their texture coordinates.
    TempDir dir("obj");
    std::string path = write_text(dir.file("seam.obj"),
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                  "f 1/1 2/2 3/3\nf 1/5 3/5 4/4\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 2);
    CHECK(mesh.vertex_count() == 6);
    // The smooth normals still agree across the seam (same plane).
    for (const auto& n : mesh.parts[0].normals) CHECK(n.z == Approx(1.0f));
}

TEST_CASE("OBJ degenerate and non-finite vertices never yield bad normals", "[assets][obj]") {
    TempDir dir("obj");
    SECTION("zero-area triangle") {
        std::string path = write_text(dir.file("flat.obj"), "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n");
        facet::Mesh mesh = facet::load_obj(path);
        check_sane(mesh);  // normals are still unit length
    }
    SECTION("non-finite coordinates") {
        std::string path =
            write_text(dir.file("nan.obj"), "v 0 0 0\nv 1 0 0\nv nan inf 0\nf 1 2 3\n");
        // tinyobjloader would read the words as 0 and move the vertex.
        require_input_error([&] { facet::load_obj(path); },
                            "nan.obj:3:3: 'nan' is not a finite number");
        const std::string normal = write_text(
            dir.file("normal.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 Inf\nf 1//1 2//1 3//1\n");
        require_input_error([&] { facet::load_obj(normal); }, "normal.obj:4:8: 'Inf'");
    }
    SECTION("a comment after the numbers is not data") {
        const std::string path = write_text(dir.file("comment.obj"),
                                            "v 0 0 0 # origin\nv 1 0 0\nv 0 1 0 # apex\nf 1 2 3\n");
        CHECK(facet::load_obj(path).triangle_count() == 1);
    }
}

TEST_CASE("OBJ text encodings: UTF-8 with BOM and UTF-16 both ways", "[assets][obj]") {
    const std::string text = unit_cube_obj_without_normals();
    std::string utf8 = "\xEF\xBB\xBF" + text;
    std::string le = "\xFF\xFE", be = "\xFE\xFF";
    for (char c : text) {
        le += c;
        le += '\0';
        be += '\0';
        be += c;
    }
    TempDir dir("obj");
    for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
             {"bom8.obj", utf8}, {"utf16le.obj", le}, {"utf16be.obj", be}}) {
        DYNAMIC_SECTION(name) {
            facet::Mesh mesh = facet::load_obj(write_text(dir.file(name), bytes));
            check_sane(mesh);
            CHECK(mesh.triangle_count() == 12);
            require_bounds(mesh, glm::vec3(-1), glm::vec3(1));
            require_closed_and_oriented(mesh);
        }
    }
}
