// Wavefront OBJ loading (src/assets/obj_loader.cpp) of the awkward real files
// among assimp's test models, checked against an independent reading of
// their text.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"

namespace fs = std::filesystem;
using namespace facet::test;

namespace {

const std::string kObjDir = kAssimpModels + "OBJ/";

// --- An independent reading of OBJ text -----------------------------------

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
    std::istringstream in(as_ascii(read_file(path)));
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

// The file's normals are all axis directions (as a cube's faces have).
void require_axis_aligned_normals(const facet::Mesh& mesh) {
    for (const auto& part : mesh.parts)
        for (const auto& n : part.normals)
            CHECK(std::abs(n.x) + std::abs(n.y) + std::abs(n.z) == Approx(1.0f));
}

}  // namespace

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
            require_bounds(mesh, expected.bounds.min, expected.bounds.max, 1e-4f);
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
            require_axis_aligned_normals(mesh);
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
            std::istringstream in(read_file(kObjDir + name));
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
    require_axis_aligned_normals(mesh);
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
        REQUIRE(m.base_color_map.texture != nullptr);
        CHECK(m.base_color_map.texture->width > 0);
        CHECK(m.base_color_map.texture->height > 0);
        CHECK(m.base_color_map.texture->level(0).bytes8.size() +
                  m.base_color_map.texture->level(0).half.size() ==
              static_cast<size_t>(m.base_color_map.texture->width) *
                  m.base_color_map.texture->height);
        ++textured;
    }
    CHECK(textured == maps.size());
    for (const auto& part : mesh.parts) {
        const auto& m = material_of(mesh, part);
        if (m.base_color_map.texture) CHECK(part.uvs.size() == part.positions.size());
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
    const std::string dir = kAssimpModels + "invalid/";
    require_input_error([&] { facet::load_mesh(dir + "empty.obj"); }, "empty.obj");
    require_input_error([&] { facet::load_mesh(dir + "malformed.obj"); }, "malformed.obj");
    // malformed2.obj: a face with no corners and an unknown material; the
    // other five quads are fine.
    facet::Mesh mesh = facet::load_mesh(dir + "malformed2.obj");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 10);
}

// Every OBJ of assimp's test models: the three without faces are refused,
// every other one loads sanely.
TEST_CASE("OBJ every real file loads sanely, or is refused as expected", "[assets][obj][real]") {
    const std::set<std::string> without_faces = {"point_cloud.obj", "testline.obj",
                                                 "testpoints.obj"};
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(kObjDir)) {
        if (entry.path().extension() != ".obj") continue;
        ++files;
        const std::string name = entry.path().filename().string();
        const std::string path = entry.path().string();
        DYNAMIC_SECTION(name) {
            if (without_faces.count(name))
                require_input_error([&] { facet::load_mesh(path); }, "has no faces");
            else
                check_sane(facet::load_mesh(path));
        }
    }
    CHECK(files > 15);
}
