// Wavefront OBJ loading (src/assets/obj_loader.cpp): small files with known
// answers written here, and the awkward real files of assimp's test models.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "assets/mesh.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using facet::test::TempDir;
using facet::test::write_text;

namespace {

const std::string kObjDir = "/usr/share/assimp/models/OBJ/";
constexpr double kPi = 3.14159265358979323846;

glm::vec3 corner(const facet::MeshPart& p, size_t t, int k) {
    return p.positions[p.indices[3 * t + k]];
}

// Twice-area vector of triangle t: its direction is the counter-clockwise normal.
glm::vec3 face_cross(const facet::MeshPart& p, size_t t) {
    glm::vec3 a = corner(p, t, 0), b = corner(p, t, 1), c = corner(p, t, 2);
    return glm::cross(b - a, c - a);
}

float total_area(const facet::Mesh& mesh) {
    double sum = 0;
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t)
            sum += 0.5 * glm::length(face_cross(part, t));
    return static_cast<float>(sum);
}

// Invariants every loaded mesh must satisfy, whatever the file looked like.
void check_sane(const facet::Mesh& mesh) {
    REQUIRE(mesh.triangle_count() > 0);
    for (const auto& part : mesh.parts) {
        REQUIRE(part.indices.size() % 3 == 0);
        REQUIRE(part.normals.size() == part.positions.size());
        REQUIRE((part.uvs.empty() || part.uvs.size() == part.positions.size()));
        REQUIRE(part.material < mesh.materials.size());
        for (uint32_t i : part.indices) REQUIRE(i < part.positions.size());
        for (const auto& p : part.positions)
            REQUIRE((std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)));
        for (const auto& n : part.normals) REQUIRE(glm::length(n) == Approx(1.0f).margin(1e-4));
        for (const auto& uv : part.uvs) REQUIRE((std::isfinite(uv.x) && std::isfinite(uv.y)));
    }
    facet::Bounds b = mesh.bounds();
    REQUIRE_FALSE(b.empty());
    for (int k = 0; k < 3; ++k) {
        REQUIRE(std::isfinite(b.min[k]));
        REQUIRE(std::isfinite(b.max[k]));
    }
}

// Runs `load` and requires a facet::Error with the invalid-input code whose
// message contains `needle` (normally the file name). Any other exception
// escapes and fails the test.
template <typename F>
void require_input_error(F&& load, const std::string& needle) {
    try {
        load();
        FAIL("expected facet::Error mentioning '" << needle << "'");
    } catch (const facet::Error& e) {
        CHECK(e.code() == facet::ExitCode::invalid_input);
        CHECK_THAT(e.what(), Catch::Contains(needle));
    }
}

void require_bounds(const facet::Mesh& mesh, glm::vec3 lo, glm::vec3 hi, float eps = 1e-5f) {
    facet::Bounds b = mesh.bounds();
    for (int k = 0; k < 3; ++k) {
        CHECK(b.min[k] == Approx(lo[k]).margin(eps));
        CHECK(b.max[k] == Approx(hi[k]).margin(eps));
    }
}

// Welds positions within `eps` and checks that every undirected edge is used by
// exactly two triangles, once in each direction (closed and consistently wound).
void require_closed_and_oriented(const facet::Mesh& mesh, float eps = 1e-5f) {
    std::vector<glm::vec3> welded;
    auto weld = [&](glm::vec3 p) {
        for (size_t i = 0; i < welded.size(); ++i)
            if (glm::length(welded[i] - p) <= eps) return i;
        welded.push_back(p);
        return welded.size() - 1;
    };
    std::map<std::pair<size_t, size_t>, int> directed;
    for (const auto& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            size_t v[3];
            for (int k = 0; k < 3; ++k) v[k] = weld(corner(part, t, k));
            for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
        }
    for (const auto& [edge, count] : directed) {
        INFO("edge " << edge.first << "-" << edge.second);
        REQUIRE(count == 1);
        auto back = directed.find({edge.second, edge.first});
        REQUIRE(back != directed.end());
        REQUIRE(back->second == 1);
    }
}

const facet::Material& material_of(const facet::Mesh& mesh, const facet::MeshPart& part) {
    return mesh.materials.at(part.material);
}

// --- An independent reading of OBJ text, for the real files ---------------

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// UTF-16 (with BOM) to plain bytes; the test files only use ASCII.
std::string as_ascii(const std::string& raw) {
    if (raw.size() >= 2 && static_cast<unsigned char>(raw[0]) == 0xFE &&
        static_cast<unsigned char>(raw[1]) == 0xFF) {
        std::string out;
        for (size_t i = 3; i < raw.size(); i += 2) out += raw[i];
        return out;
    }
    if (raw.size() >= 2 && static_cast<unsigned char>(raw[0]) == 0xFF &&
        static_cast<unsigned char>(raw[1]) == 0xFE) {
        std::string out;
        for (size_t i = 2; i < raw.size(); i += 2) out += raw[i];
        return out;
    }
    return raw;
}

struct ObjCount {
    size_t triangles = 0;                       // sum over faces of (corners - 2)
    std::map<std::string, size_t> by_material;  // same, per `usemtl` name
    facet::Bounds bounds;                       // of vertices that faces use
};

ObjCount count_obj(const std::string& path) {
    std::istringstream in(as_ascii(read_bytes(path)));
    std::string line, material;
    std::vector<glm::vec3> v;
    ObjCount out;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") {
            glm::vec3 p(0);
            std::string x, y, z;
            ls >> x >> y >> z;
            p = {std::strtof(x.c_str(), nullptr), std::strtof(y.c_str(), nullptr),
                 std::strtof(z.c_str(), nullptr)};
            v.push_back(p);
        } else if (tag == "usemtl") {
            std::getline(ls >> std::ws, material);
        } else if (tag == "f") {
            std::string token;
            std::vector<long> corners;
            while (ls >> token) {
                if (token[0] == '#') break;
                long i = std::strtol(token.c_str(), nullptr, 10);
                corners.push_back(i < 0 ? static_cast<long>(v.size()) + i : i - 1);
            }
            if (corners.size() < 3) continue;
            out.triangles += corners.size() - 2;
            out.by_material[material] += corners.size() - 2;
            for (long c : corners) out.bounds.add(v.at(static_cast<size_t>(c)));
        }
    }
    return out;
}

// --- Writing small test files ---------------------------------------------

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

// Area vector (Newell) of a closed planar polygon: normal times area.
glm::vec3 polygon_area_vector(const std::vector<glm::vec3>& pts) {
    glm::vec3 sum(0);
    for (size_t i = 0; i < pts.size(); ++i) sum += glm::cross(pts[i], pts[(i + 1) % pts.size()]);
    return 0.5f * sum;
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
            glm::vec3 centroid =
                (corner(part, t, 0) + corner(part, t, 1) + corner(part, t, 2)) / 3.0f;
            CHECK(inside_polygon(pts, centroid, u, v));
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

void write_png(const std::string& path, const facet::ColorImage& image) {
    auto bytes = facet::encode_png_color(image, 6);
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
}

// 2x2 texture: red, green / blue, white, all exactly representable in sRGB bytes.
facet::ColorImage checker_image() {
    facet::ColorImage img(2, 2);
    img.at(0, 0) = {1, 0, 0, 1};
    img.at(1, 0) = {0, 1, 0, 1};
    img.at(0, 1) = {0, 0, 1, 1};
    img.at(1, 1) = {1, 1, 1, 1};
    return img;
}

}  // namespace

// --- Small files with known answers ----------------------------------------

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
            std::vector<glm::vec2> ring;
            for (int i = 0; i < n; ++i)
                ring.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)});
            // Far from the origin and in a tilted plane, so no axis or origin is special.
            require_triangulates(embed(ring, {10, -7, 3}, glm::normalize(glm::vec3(1, 1, 0)),
                                       glm::normalize(glm::vec3(-1, 1, 1))));
        }
    }
}

TEST_CASE("OBJ concave polygons are triangulated inside their outline", "[assets][obj]") {
    SECTION("dart-shaped quad whose shorter diagonal lies outside it") {
        require_triangulates(
            embed({{0, 0}, {1, 0.5f}, {2, 0}, {1, 5}}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    }
    SECTION("L shape in the XY plane") {
        require_triangulates(embed({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {0, 0, 0},
                                   {1, 0, 0}, {0, 1, 0}));
    }
    SECTION("L shape far from the origin") {
        require_triangulates(embed({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {5, 5, 0},
                                   {1, 0, 0}, {0, 1, 0}));
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
            glm::vec3 centroid =
                (corner(part, t, 0) + corner(part, t, 1) + corner(part, t, 2)) / 3.0f;
            CHECK(glm::dot(f, centroid) > 0);  // faces point outward
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

TEST_CASE("OBJ materials: Kd colour, shininess and map_Kd texture", "[assets][obj]") {
    TempDir dir("obj");
    write_png(dir.file("textures/checker.png"), checker_image());
    write_text(dir.file("scene.mtl"),
               "# two materials\n"
               "newmtl red\nKd 0.8 0.1 0.2\nKs 0.5 0.5 0.5\nNs 64\n\n"
               "newmtl textured\nKd 0 0 0\nmap_Kd textures/checker.png\n");
    std::string path = write_text(dir.file("scene.obj"),
                                  "mtllib scene.mtl\n"
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                  "vt 0 0\nvt 1 0\nvt 1 1\n"
                                  "usemtl red\nf 1 2 3 4\n"
                                  "usemtl textured\nf 1/1 2/2 5/3\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 2);
    std::map<std::string, const facet::MeshPart*> by_name;
    for (const auto& part : mesh.parts) by_name[material_of(mesh, part).name] = &part;
    REQUIRE(by_name.count("red"));
    REQUIRE(by_name.count("textured"));
    CHECK(by_name["red"]->triangle_count() == 2);
    CHECK(by_name["textured"]->triangle_count() == 1);

    const auto& red = material_of(mesh, *by_name["red"]);
    CHECK(red.color.r == Approx(0.8f));
    CHECK(red.color.g == Approx(0.1f));
    CHECK(red.color.b == Approx(0.2f));
    CHECK(red.shininess == Approx(64.0f));
    CHECK(red.specular == Approx(0.5f));
    CHECK(red.texture == nullptr);

    const auto& textured = material_of(mesh, *by_name["textured"]);
    REQUIRE(textured.texture != nullptr);
    CHECK(textured.texture->width == 2);
    CHECK(textured.texture->height == 2);
    const auto& texels = textured.texture->texels;
    REQUIRE(texels.size() == 4);
    CHECK(texels[0] == glm::vec4(1, 0, 0, 1));  // top-left red
    CHECK(texels[1] == glm::vec4(0, 1, 0, 1));
    CHECK(texels[2] == glm::vec4(0, 0, 1, 1));
    CHECK(texels[3] == glm::vec4(1, 1, 1, 1));
    // Kd 0 0 0 next to a map means "use the map": the texture must not be blacked out.
    CHECK(textured.color == glm::vec3(1));
}

TEST_CASE("OBJ map_Kd written with Windows backslashes is found", "[assets][obj]") {
    TempDir dir("obj");
    write_png(dir.file("maps/checker.png"), checker_image());
    write_text(dir.file("win.mtl"), "newmtl m\r\nKd 1 1 1\r\nmap_Kd .\\maps\\checker.png\r\n");
    std::string path = write_text(dir.file("win.obj"),
                                  "mtllib win.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvt 0 0\r\n"
                                  "usemtl m\r\nf 1/1 2/1 3/1\r\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 1);
    const auto& mat = material_of(mesh, mesh.parts[0]);
    CHECK(mat.name == "m");
    REQUIRE(mat.texture != nullptr);
    CHECK(mat.texture->width == 2);
}

TEST_CASE("OBJ faces without a known material use a default material", "[assets][obj]") {
    TempDir dir("obj");
    write_text(dir.file("one.mtl"), "newmtl known\nKd 0 0 1\n");
    std::string path = write_text(dir.file("mixed.obj"),
                                  "mtllib one.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "f 1 2 3\nusemtl known\nf 1 2 3\nusemtl unknown\nf 3 2 1\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 3);
    size_t known = 0, other = 0;
    for (const auto& part : mesh.parts) {
        if (material_of(mesh, part).name == "known") {
            known += part.triangle_count();
            CHECK(material_of(mesh, part).color == glm::vec3(0, 0, 1));
        } else {
            other += part.triangle_count();
        }
    }
    CHECK(known == 1);
    CHECK(other == 2);
}

TEST_CASE("OBJ with a missing .mtl still loads its geometry", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(
        dir.file("nomtl.obj"), "mtllib absent.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 1);
}

TEST_CASE("OBJ map_Kd naming a missing image is an error naming both files", "[assets][obj]") {
    TempDir dir("obj");
    write_text(dir.file("m.mtl"), "newmtl m\nmap_Kd nowhere.png\n");
    std::string path = write_text(dir.file("needs_tex.obj"),
                                  "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
    require_input_error([&] { facet::load_obj(path); }, "needs_tex.obj");
    require_input_error([&] { facet::load_obj(path); }, "nowhere.png");
}

TEST_CASE("OBJ face indices past the end are errors naming the file", "[assets][obj]") {
    TempDir dir("obj");
    const std::string verts = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    SECTION("triangle") {
        std::string path = write_text(dir.file("bad_tri.obj"), verts + "f 1 2 5\n");
        require_input_error([&] { facet::load_obj(path); }, "bad_tri.obj");
    }
    SECTION("quad, next to a valid face") {
        std::string path = write_text(dir.file("bad_quad.obj"), verts + "f 1 2 3\nf 1 2 3 9\n");
        require_input_error([&] { facet::load_obj(path); }, "bad_quad.obj");
    }
    SECTION("pentagon") {
        std::string path = write_text(dir.file("bad_poly.obj"), verts + "f 1 2 3 4 77\n");
        require_input_error([&] { facet::load_obj(path); }, "bad_poly.obj");
    }
    SECTION("huge index") {
        std::string path = write_text(dir.file("bad_huge.obj"), verts + "f 1 2 2147483647\n");
        require_input_error([&] { facet::load_obj(path); }, "bad_huge.obj");
    }
    SECTION("negative index before the first vertex") {
        std::string path = write_text(dir.file("bad_neg.obj"), verts + "f -5 1 2\n");
        require_input_error([&] { facet::load_obj(path); }, "bad_neg.obj");
    }
    SECTION("negative index before the first vertex in a quad") {
        std::string path = write_text(dir.file("bad_negquad.obj"), verts + "f 1 2 3\nf -9 1 2 3\n");
        require_input_error([&] { facet::load_obj(path); }, "bad_negquad.obj");
    }
    SECTION("index zero") {
        std::string path = write_text(dir.file("bad_zero.obj"), verts + "f 0 1 2\n");
        require_input_error([&] { facet::load_obj(path); }, "bad_zero.obj");
    }
}

TEST_CASE("OBJ normal and texture indices past the end do not break loading", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(dir.file("odd_attr.obj"),
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
                                  "f 1/7/9 2/1/1 3/1/1\n");
    facet::Mesh mesh = facet::load_obj(path);  // the stray indices are ignored, not read
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 1);
    for (const auto& n : mesh.parts[0].normals) CHECK(n.z == Approx(1.0f));
}

TEST_CASE("OBJ files without faces are errors", "[assets][obj]") {
    TempDir dir("obj");
    SECTION("empty file") {
        std::string path = write_text(dir.file("empty.obj"), "");
        require_input_error([&] { facet::load_obj(path); }, "empty.obj");
    }
    SECTION("only comments and blank lines") {
        std::string path =
            write_text(dir.file("comments.obj"), "# nothing here\n\n   \n# at all\n");
        require_input_error([&] { facet::load_obj(path); }, "comments.obj");
    }
    SECTION("only vertices") {
        std::string path = write_text(dir.file("verts.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        require_input_error([&] { facet::load_obj(path); }, "verts.obj");
    }
    SECTION("points and lines") {
        std::string path =
            write_text(dir.file("lines.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\nl 1 2 3\n");
        require_input_error([&] { facet::load_obj(path); }, "lines.obj");
    }
    SECTION("faces with fewer than three corners") {
        std::string path = write_text(dir.file("short.obj"), "v 0 0 0\nv 1 0 0\nf 1 2\nf 1\nf\n");
        require_input_error([&] { facet::load_obj(path); }, "short.obj");
    }
    SECTION("binary garbage") {
        std::string garbage;
        uint32_t x = 12345;
        for (int i = 0; i < 4096; ++i) {
            x = x * 1664525u + 1013904223u;
            garbage += static_cast<char>(0x80 | (x >> 24));  // never ASCII, so never a keyword
        }
        std::string path = write_text(dir.file("garbage.obj"), garbage);
        require_input_error([&] { facet::load_obj(path); }, "garbage.obj");
    }
}

TEST_CASE("OBJ missing file or folder is an error naming it", "[assets][obj]") {
    TempDir dir("obj");
    std::string missing = dir.file("no_such_model.obj");
    require_input_error([&] { facet::load_obj(missing); }, "no_such_model.obj");
    require_input_error([&] { facet::load_mesh(missing); }, "no_such_model.obj");
    fs::create_directories(dir.file("folder.obj"));
    require_input_error([&] { facet::load_mesh(dir.file("folder.obj")); }, "folder.obj");
}

TEST_CASE("load_mesh picks the OBJ loader by extension, ignoring case", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(dir.file("UPPER.OBJ"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    facet::Mesh mesh = facet::load_mesh(path);
    CHECK(mesh.triangle_count() == 1);
    std::string other = write_text(dir.file("model.stl"), "solid x\nendsolid x\n");
    require_input_error([&] { facet::load_mesh(other); }, "model.stl");
    std::string none = write_text(dir.file("model"), "v 0 0 0\n");
    require_input_error([&] { facet::load_mesh(none); }, "model");
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
        try {
            facet::Mesh mesh = facet::load_obj(path);
            check_sane(mesh);  // if the parser read the value as something finite
        } catch (const facet::Error& e) {
            CHECK(e.code() == facet::ExitCode::invalid_input);
            CHECK_THAT(e.what(), Catch::Contains("nan.obj"));
        }
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

TEST_CASE("OBJ material libraries: spaces in names, backslashes, odd folders", "[assets][obj]") {
    TempDir dir("obj");
    SECTION("usemtl with a name containing spaces") {
        write_text(dir.file("spaced.mtl"),
                   "newmtl Matte Red  Paint\nKd 1 0 0\nnewmtl Matte\nKd 0 1 0\n");
        std::string path =
            write_text(dir.file("spaced.obj"),
                       "mtllib spaced.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                       "usemtl   Matte Red  Paint  \nf 1 2 3\nusemtl Matte\nf 3 2 1\n");
        facet::Mesh mesh = facet::load_obj(path);
        check_sane(mesh);
        std::map<std::string, glm::vec3> colour;
        for (const auto& part : mesh.parts)
            colour[material_of(mesh, part).name] = material_of(mesh, part).color;
        REQUIRE(colour.size() == 2);
        REQUIRE(colour.count("Matte Red Paint"));
        CHECK(colour["Matte Red Paint"] == glm::vec3(1, 0, 0));
        REQUIRE(colour.count("Matte"));
        CHECK(colour["Matte"] == glm::vec3(0, 1, 0));
    }
    SECTION("mtllib written with backslashes, in a folder whose name has a colon") {
        write_text(dir.file("a:b/libs/blue.mtl"), "newmtl blue\nKd 0 0 1\n");
        std::string path = write_text(
            dir.file("a:b/model.obj"),
            "mtllib .\\libs\\blue.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl blue\nf 1 2 3\n");
        facet::Mesh mesh = facet::load_obj(path);
        REQUIRE(mesh.parts.size() == 1);
        CHECK(material_of(mesh, mesh.parts[0]).name == "blue");
        CHECK(material_of(mesh, mesh.parts[0]).color == glm::vec3(0, 0, 1));
    }
}

TEST_CASE("OBJ faces with more than 255 corners", "[assets][obj]") {
    // tinyobjloader counts face corners in a byte; these faces must neither
    // wrap around nor shift the faces after them.
    std::vector<glm::vec2> ring;
    const int n = 300;
    for (int i = 0; i < n; ++i)
        ring.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)});
    std::vector<glm::vec3> pts = embed(ring, {0, 0, 2}, {1, 0, 0}, {0, 1, 0});
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

// --- Real files from assimp's test models ----------------------------------

TEST_CASE("OBJ real files: triangle counts match an independent count", "[assets][obj][real]") {
    const std::vector<std::string> files = {"box.obj",
                                            "box_UTF16BE.obj",
                                            "box_without_lineending.obj",
                                            "box_mat_with_spaces.obj",
                                            "concave_polygon.obj",
                                            "space_in_material_name.obj",
                                            "cube_usemtl.obj",
                                            "cube_mtllib_after_g.obj",
                                            "cube_with_vertexcolors.obj",
                                            "cube_with_vertexcolors_uni.obj",
                                            "number_formats.obj",
                                            "multiple_spaces.obj",
                                            "regr_3429812.obj",
                                            "testmixed.obj",
                                            "spider.obj",
                                            "WusonOBJ.obj",
                                            "regr01.obj",
                                            "empty_mat.obj"};
    for (const auto& name : files) {
        DYNAMIC_SECTION(name) {
            ObjCount expected = count_obj(kObjDir + name);
            REQUIRE(expected.triangles > 0);
            facet::Mesh mesh = facet::load_obj(kObjDir + name);
            check_sane(mesh);
            CHECK(mesh.triangle_count() == expected.triangles);
            facet::Bounds b = mesh.bounds();
            for (int k = 0; k < 3; ++k) {
                CHECK(b.min[k] == Approx(expected.bounds.min[k]).margin(1e-4));
                CHECK(b.max[k] == Approx(expected.bounds.max[k]).margin(1e-4));
            }
        }
    }
}

TEST_CASE("OBJ real box files are closed unit cubes", "[assets][obj][real]") {
    for (const std::string name : {"box.obj", "box_UTF16BE.obj", "box_without_lineending.obj"}) {
        DYNAMIC_SECTION(name) {
            facet::Mesh mesh = facet::load_obj(kObjDir + name);
            CHECK(mesh.triangle_count() == 12);
            require_bounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
            require_closed_and_oriented(mesh);
            CHECK(total_area(mesh) == Approx(6.0f));
            // No normals in the file: flat per face, axis aligned.
            for (const auto& part : mesh.parts)
                for (const auto& n : part.normals)
                    CHECK(std::abs(n.x) + std::abs(n.y) + std::abs(n.z) == Approx(1.0f));
        }
    }
}

TEST_CASE("OBJ real box with a 900-corner face loads without overflow", "[assets][obj][real]") {
    // box_longline.obj repeats the four corners of one side ~230 times in one
    // face; whatever that face becomes, the other five sides must survive.
    facet::Mesh mesh = facet::load_obj(kObjDir + "box_longline.obj");
    check_sane(mesh);
    CHECK(mesh.triangle_count() >= 10);
    require_bounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
}

TEST_CASE("OBJ real concave polygon keeps its area", "[assets][obj][real]") {
    // A ring-shaped LightWave polygon of 66 corners in the plane x = -1.146,
    // its hole joined to the outside by a doubled edge.
    for (const std::string name : {"concave_polygon.obj", "space_in_material_name.obj"}) {
        DYNAMIC_SECTION(name) {
            std::istringstream in(read_bytes(kObjDir + name));
            std::string line;
            std::vector<glm::vec3> v, poly;
            while (std::getline(in, line)) {
                std::istringstream ls(line);
                std::string tag;
                ls >> tag;
                if (tag == "v") {
                    glm::vec3 p;
                    ls >> p.x >> p.y >> p.z;
                    v.push_back(p);
                } else if (tag == "f") {
                    std::string tok;
                    while (ls >> tok) poly.push_back(v.at(std::stoul(tok) - 1));
                }
            }
            REQUIRE(poly.size() == 66);
            float area = glm::length(polygon_area_vector(poly));
            facet::Mesh mesh = facet::load_obj(kObjDir + name);
            check_sane(mesh);
            CHECK(mesh.triangle_count() == 64);
            CHECK(total_area(mesh) == Approx(area).epsilon(1e-3));
            for (const auto& part : mesh.parts)
                for (size_t t = 0; t < part.triangle_count(); ++t) {
                    glm::vec3 c = face_cross(part, t);
                    CHECK(c.x >= 0);  // the file's normal is +X: nothing folded over
                }
        }
    }
}

TEST_CASE("OBJ real cube_usemtl splits parts by material", "[assets][obj][real]") {
    ObjCount expected = count_obj(kObjDir + "cube_usemtl.obj");
    // From the file: mtl 6 faces, mtl2 4, mtl3 2 (mtl3 is not in the .mtl).
    REQUIRE(expected.by_material.at("mtl") == 6);
    REQUIRE(expected.by_material.at("mtl2") == 4);
    REQUIRE(expected.by_material.at("mtl3") == 2);
    facet::Mesh mesh = facet::load_obj(kObjDir + "cube_usemtl.obj");
    check_sane(mesh);
    std::map<std::string, size_t> got;
    for (const auto& part : mesh.parts) got[material_of(mesh, part).name] += part.triangle_count();
    CHECK(got["mtl"] == 6);
    CHECK(got["mtl2"] == 4);
    CHECK(got["mtl3"] + got["default"] == 2);
    for (const auto& part : mesh.parts) {
        const auto& m = material_of(mesh, part);
        if (m.name == "mtl") CHECK(m.shininess == Approx(200.0f));
        if (m.name == "mtl2") CHECK(m.specular == Approx(0.375f));
    }
    // The file gives normals; each is one of the six axis directions.
    for (const auto& part : mesh.parts)
        for (const auto& n : part.normals)
            CHECK(std::abs(n.x) + std::abs(n.y) + std::abs(n.z) == Approx(1.0f));
    require_bounds(mesh, {0, 0, 0}, {1, 1, 1});
    require_closed_and_oriented(mesh);
}

TEST_CASE("OBJ real number formats are parsed", "[assets][obj][real]") {
    // f 1 2 4 uses "v 0 0 0", "v 1 2. 3.0" and "v -1 -2. -3.0".
    facet::Mesh mesh = facet::load_obj(kObjDir + "number_formats.obj");
    CHECK(mesh.triangle_count() == 1);
    require_bounds(mesh, {-1, -2, -3}, {1, 2, 3});
    check_sane(mesh);  // the triangle is degenerate (collinear); normals stay unit
}

TEST_CASE("OBJ real material name with spaces", "[assets][obj][real]") {
    facet::Mesh mesh = facet::load_obj(kObjDir + "space_in_material_name.obj");
    REQUIRE(mesh.parts.size() == 1);
    const auto& m = material_of(mesh, mesh.parts[0]);
    CHECK(m.name == "Hard Shiny Plastic White");
    CHECK(m.color.r == Approx(0.141176f));
    CHECK(m.color.g == Approx(0.184314f));
    CHECK(m.color.b == Approx(0.411765f));
}

TEST_CASE("OBJ real spider loads with all five textures", "[assets][obj][real]") {
    facet::Mesh mesh = facet::load_obj(kObjDir + "spider.obj");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == count_obj(kObjDir + "spider.obj").triangles);
    // spider.mtl: five materials, each with a map_Kd written as ".\name.jpg".
    std::map<std::string, std::string> maps = {{"Skin", "wal67ar_small.jpg"},
                                               {"Brusttex", "wal69ar_small.jpg"},
                                               {"HLeibTex", "SpiderTex.jpg"},
                                               {"BeinTex", "drkwood2.jpg"},
                                               {"Augentex", "engineflare1.jpg"}};
    size_t textured = 0;
    for (const auto& m : mesh.materials) {
        if (!maps.count(m.name)) continue;
        INFO("material " << m.name);
        REQUIRE(m.texture != nullptr);
        CHECK(m.texture->width > 0);
        CHECK(m.texture->height > 0);
        CHECK(m.texture->texels.size() ==
              static_cast<size_t>(m.texture->width) * m.texture->height);
        ++textured;
    }
    CHECK(textured == maps.size());
    for (const auto& part : mesh.parts) {
        const auto& m = material_of(mesh, part);
        if (m.texture) CHECK(part.uvs.size() == part.positions.size());
    }
}

TEST_CASE("OBJ real files without faces are errors", "[assets][obj][real]") {
    for (const std::string name : {"testpoints.obj", "point_cloud.obj", "testline.obj"}) {
        DYNAMIC_SECTION(name) {
            REQUIRE(count_obj(kObjDir + name).triangles == 0);
            require_input_error([&] { facet::load_obj(kObjDir + name); }, name);
        }
    }
}

TEST_CASE("OBJ real invalid files are errors, not crashes", "[assets][obj][real]") {
    const std::string dir = "/usr/share/assimp/models/invalid/";
    require_input_error([&] { facet::load_mesh(dir + "empty.obj"); }, "empty.obj");
    require_input_error([&] { facet::load_mesh(dir + "malformed.obj"); }, "malformed.obj");
    // malformed2.obj: a face with no corners and an unknown material; the
    // other five quads are fine.
    facet::Mesh mesh = facet::load_mesh(dir + "malformed2.obj");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 10);
}

TEST_CASE("OBJ every real file loads sanely or is a facet::Error", "[assets][obj][real]") {
    for (const auto& entry : fs::directory_iterator(kObjDir)) {
        if (entry.path().extension() != ".obj") continue;
        const std::string path = entry.path().string();
        DYNAMIC_SECTION(entry.path().filename().string()) {
            try {
                facet::Mesh mesh = facet::load_mesh(path);
                check_sane(mesh);
            } catch (const facet::Error& e) {
                CHECK(e.code() == facet::ExitCode::invalid_input);
                CHECK_THAT(e.what(), Catch::Contains(entry.path().filename().string()));
            }
        }
    }
}
