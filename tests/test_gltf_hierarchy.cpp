// glTF 2.0 loading (src/assets/gltf_loader.cpp), flattening the node tree:
// transforms and their effect on positions, normals and winding, node
// hierarchies, cycles and files without scenes. The files are tiny ones with
// known answers, built here.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"

using namespace facet::test;
using nlohmann::json;

namespace {

// Cube [-1,1]^3 as 8 shared corners and 12 outward counter-clockwise triangles.
const std::vector<float> kCubeCorners = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                         -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
const std::vector<uint16_t> kCubeIndices = {4, 5, 6, 4, 6, 7, 1, 0, 3, 1, 3, 2, 5, 1, 2, 5, 2, 6,
                                            0, 4, 7, 0, 7, 3, 7, 6, 2, 7, 2, 3, 0, 1, 5, 0, 5, 4};

json cube_primitive(Gltf& g) {
    return {{"attributes", {{"POSITION", g.floats(kCubeCorners, "VEC3")}}},
            {"indices", g.indices(kCubeIndices, kUShort)}};
}

// A Gltf whose meshes can show the triangle: `mesh` is its index.
struct TriangleDoc {
    Gltf g;
    int mesh = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
};

}  // namespace

// --- Node transforms --------------------------------------------------------

TEST_CASE("glTF node transforms are applied to positions", "[assets][gltf]") {
    TempDir dir("gltf");
    struct Case {
        const char* name;
        json node;
        std::vector<glm::vec3> want;  // images of (0,0,0), (1,0,0), (0,1,0)
    };
    const float h = std::sqrt(0.5f);
    const std::vector<Case> cases = {
        {"translation", {{"translation", {1, 2, 3}}}, {{1, 2, 3}, {2, 2, 3}, {1, 3, 3}}},
        {"rotation 90 degrees about Y",
         {{"rotation", {0, h, 0, h}}},
         {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}},
        {"scale", {{"scale", {2, 3, 4}}}, {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}},
        // T * R * S: scale x by 2, turn 90 degrees about Z, then move by +X.
        {"translation, rotation and scale together",
         {{"translation", {1, 0, 0}}, {"rotation", {0, 0, h, h}}, {"scale", {2, 1, 1}}},
         {{1, 0, 0}, {1, 2, 0}, {0, 0, 0}}},
        {"unnormalised rotation quaternion",
         {{"rotation", {0, 0, 2, 2}}},
         {{0, 0, 0}, {0, 1, 0}, {-1, 0, 0}}},
        {"matrix, column-major translation",
         {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}}},
         {{5, 6, 7}, {6, 6, 7}, {5, 7, 7}}},
        // Columns are the images of the axes: x -> (0,2,0), y -> (-3,0,0).
        {"matrix, rotation and scale",
         {{"matrix", {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}},
         {{0, 0, 0}, {0, 2, 0}, {-3, 0, 0}}},
    };
    for (const auto& c : cases) {
        DYNAMIC_SECTION(c.name) {
            facet::Mesh mesh =
                facet::load_gltf(single_mesh_file(dir.file("node.gltf"), kTriangle, c.node));
            check_sane(mesh);
            auto corners = all_corners(mesh);
            REQUIRE(corners.size() == 3);
            for (int k = 0; k < 3; ++k) require_vec3(corners[k], c.want[k], 1e-5f);
        }
    }
}

TEST_CASE("glTF node hierarchy composes parent and child transforms", "[assets][gltf]") {
    TempDir dir("gltf");
    TriangleDoc t;
    Gltf& g = t.g;
    int child = g.node({{"mesh", t.mesh}, {"translation", {0, 1, 0}}});
    int parent = g.node({{"children", {child}}, {"translation", {10, 0, 0}}, {"scale", {2, 2, 2}}});
    int other =
        g.node({{"mesh", t.mesh}, {"translation", {0, 0, -5}}});  // a second instance of the mesh
    g.scene({parent, other});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("tree.gltf")));
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 2);
    auto c = all_corners(mesh);
    REQUIRE(c.size() == 6);
    // 10 + 2 * (p + (0,1,0))
    require_vec3(c[0], {10, 2, 0});
    require_vec3(c[1], {12, 2, 0});
    require_vec3(c[2], {10, 4, 0});
    require_vec3(c[3], {0, 0, -5});
    require_vec3(c[4], {1, 0, -5});
    require_vec3(c[5], {0, 1, -5});
}

TEST_CASE("glTF normals follow the inverse transpose of the node transform", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    const float s = std::sqrt(0.5f);
    // A triangle in the plane x + y = 1, with its normal (1,1,0)/sqrt2.
    int pos = g.floats({1, 0, 0, 0, 1, 0, 1, 0, 1}, "VEC3");
    int nrm = g.floats({s, s, 0, s, s, 0, s, s, 0}, "VEC3");
    g.one_node_scene({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}},
                     {{"scale", {1, 2, 1}}});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("normals.gltf")));
    check_sane(mesh);
    // Stretching y by 2 makes the plane 2x + y = 2: normal (2,1,0)/sqrt5.
    glm::vec3 want = glm::normalize(glm::vec3(2, 1, 0));
    for (const auto& n : mesh.parts[0].normals) require_vec3(n, want, 1e-5f);
    // and that is indeed perpendicular to the transformed triangle.
    glm::vec3 f = glm::normalize(face_cross(mesh.parts[0], 0));
    CHECK(std::abs(glm::dot(f, want)) == Approx(1.0f).margin(1e-5));
}

TEST_CASE("glTF mirrored nodes flip the winding back to front-facing", "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("triangle with normals, negative scale") {
        Gltf g;
        int nrm = g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
        g.one_node_scene(
            {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}},
            {{"scale", {-1, 1, 1}}});
        facet::Mesh mesh = facet::load_gltf(g.write(dir.file("mirror.gltf")));
        check_sane(mesh);
        require_bounds(mesh, {-1, 0, 0}, {0, 1, 0});
        CHECK(face_cross(mesh.parts[0], 0).z > 0);  // still faces +Z, like its normal
        for (const auto& n : mesh.parts[0].normals) require_vec3(n, {0, 0, 1});
        require_normals_agree_with_winding(mesh, 0.99f);
    }
    for (const auto& [name, node] : std::vector<std::pair<std::string, json>>{
             {"scale -1 in x", {{"scale", {-1, 1, 1}}}},
             {"scale -1 in all axes", {{"scale", {-1, -1, -1}}}},
             {"mirror matrix", {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 3, 0, 0, 1}}}},
             {"mirror in the parent", {{"scale", {1, 1, 1}}}}}) {
        DYNAMIC_SECTION("cube, " << name) {
            std::string path;
            glm::vec3 centre(0);
            Gltf g;
            if (name == "mirror in the parent") {
                int child =
                    g.node({{"mesh", g.mesh(cube_primitive(g))}, {"translation", {2, 0, 0}}});
                g.scene({g.node({{"children", {child}}, {"scale", {1, -1, 1}}})});
                path = g.write(dir.file("mirror_parent.gltf"));
                centre = {2, 0, 0};
            } else {
                g.one_node_scene(cube_primitive(g), node);
                path = g.write(dir.file("mirror_cube.gltf"));
                if (node.contains("matrix")) centre = {3, 0, 0};
            }
            facet::Mesh mesh = facet::load_gltf(path);
            check_sane(mesh);
            CHECK(mesh.triangle_count() == 12);
            require_closed_and_oriented(mesh);
            for (const auto& part : mesh.parts)
                for (size_t t = 0; t < part.triangle_count(); ++t)
                    CHECK(glm::dot(face_cross(part, t), centroid(part, t) - centre) >
                          0);  // outward
            require_normals_agree_with_winding(mesh, 0.99f);
        }
    }
}

// --- Cycles and scenes ------------------------------------------------------

TEST_CASE("glTF node cycles and shared subtrees end quickly", "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("a node that is its own child") {
        TriangleDoc t;
        t.g.node({{"mesh", t.mesh}, {"children", {0}}});
        t.g.scene({0});
        std::string path = t.g.write(dir.file("self.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "self.gltf");
    }
    SECTION("a cycle below the root") {
        TriangleDoc t;
        t.g.node({{"children", {1}}});
        t.g.node({{"mesh", t.mesh}, {"children", {2}}});
        t.g.node({{"children", {1}}});
        t.g.scene({0});
        std::string path = t.g.write(dir.file("cycle.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "cycle.gltf");
    }
    SECTION("nodes shared by many parents, doubling at every level") {
        // Node i has node i+1 as its child twice: 2^60 paths if walked
        // naively. glTF nodes form strict trees, so the file is refused
        // before any walk.
        TriangleDoc t;
        for (int i = 0; i < 60; ++i) t.g.node({{"children", {i + 1, i + 1}}});
        t.g.node({{"mesh", t.mesh}});
        t.g.scene({0});
        std::string path = t.g.write(dir.file("diamond.gltf"));
        require_input_error([&] { facet::load_gltf(path); }, "node 1 has more than one parent");
    }
}

// A chain of `levels` nodes, the mesh on the last, each node 0.01 along x.
static std::string write_chain(TempDir& dir, int levels) {
    TriangleDoc t;
    for (int i = 0; i + 1 < levels; ++i)
        t.g.node({{"children", {i + 1}}, {"translation", {0.01, 0, 0}}});
    t.g.node({{"mesh", t.mesh}});
    t.g.scene({0});
    return t.g.write(dir.file("chain" + std::to_string(levels) + ".gltf"));
}

TEST_CASE("glTF node hierarchies of up to 256 levels load, deeper ones are refused",
          "[assets][gltf]") {
    TempDir dir("gltf");
    SECTION("256 levels, the most allowed: every translation applies") {
        const facet::Mesh mesh = facet::load_gltf(write_chain(dir, 256));
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 1);
        require_bounds(mesh, {2.55, 0, 0}, {3.55, 1, 0}, 1e-4f);
    }
    SECTION("257 levels") {
        const std::string path = write_chain(dir, 257);
        require_input_error([&] { facet::load_gltf(path); }, "deeper than 256 levels");
    }
    SECTION("5000 levels, refused without exhausting the stack") {
        const std::string path = write_chain(dir, 5000);
        require_input_error([&] { facet::load_gltf(path); }, "deeper than 256 levels");
    }
}

TEST_CASE("glTF without scenes uses every root node", "[assets][gltf]") {
    TempDir dir("gltf");
    TriangleDoc t;
    int child = t.g.node({{"mesh", t.mesh}, {"translation", {0, 0, 1}}});
    t.g.node({{"mesh", t.mesh}, {"children", {child}}});
    t.g.node({{"mesh", t.mesh}, {"translation", {0, 0, 2}}});
    facet::Mesh mesh = facet::load_gltf(t.g.write(dir.file("noscene.gltf")));
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 3);  // child once (through its parent), two roots
    require_bounds(mesh, {0, 0, 0}, {1, 1, 2});
}
