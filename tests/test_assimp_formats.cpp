// STL, PLY, FBX, Collada and 3DS through libassimp (assets/assimp_loader.cpp),
// on assimp's own test models (Debian's assimp-testmodels): one line per
// file with what it must hold, then the same model in three formats
// rendered against each other, and the refusals.
#include <catch2/catch.hpp>

#include <filesystem>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "real_asset_support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

bool have_models() {
    return std::filesystem::exists(kAssimpModels + "STL/Wuson.stl");
}

const std::string kNoModels =
    kAssimpModels + " is missing (scripts/setup.sh --tests installs assimp-testmodels)";

struct FormatCase {
    const char* file;  // under kAssimpModels
    size_t triangles;
    glm::vec3 min, max;  // bounds, to 1e-3 of the size
    size_t textured_materials;
    size_t parts_with_colors;
};

}  // namespace

TEST_CASE("assimp reads STL, PLY, FBX, Collada and 3DS files", "[assets][assimp][real]") {
    if (!have_models()) FACET_SKIP(kNoModels);
    const FormatCase cases[] = {
        {"STL/Spider_binary.stl", 1312, {-3.11489f, -4, -1.64933f}, {3.11489f, 4, 1.64933f}, 0, 0},
        {"STL/Spider_ascii.stl", 1312, {-3.11489f, -4, -1.64933f}, {3.11489f, 4, 1.64933f}, 0, 0},
        {"STL/Wuson.stl",
         3732,
         {-0.459976f, -0.000566f, -1.62224f},
         {0.459976f, 1.51525f, 1.62224f},
         0,
         0},
        {"FBX/box.fbx",
         12,
         {-0.226096f, -0.161864f, -0.0646463f},
         {0.284462f, 0.244348f, 0.46466f},
         0,
         1},
        {"Collada/duck.dae",
         4212,
         {-0.692985f, 0.0992937f, -0.613282f},
         {0.961799f, 1.6397f, 0.539252f},
         1,
         0},
        {"3DS/fels.3ds",
         768,
         {-2.22191f, -2.56474f, -0.121266f},
         {1.28288f, 2.11686f, 3.08429f},
         0,
         0},
        // A 50-unit cube placed off the origin by its node.
        {"3DS/cube_with_diffuse_texture.3DS",
         12,
         {-50, -30.5402f, -82.6177f},
         {0, 19.4598f, -32.6177f},
         1,
         0},
    };
    for (const FormatCase& c : cases) {
        INFO(c.file);
        const Mesh mesh = load_mesh(kAssimpModels + c.file);
        CHECK(mesh.loader == "assimp");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == c.triangles);
        const Bounds b = mesh.bounds();
        const float tolerance = 1e-3f * glm::length(c.max - c.min);
        CHECK(glm::length(b.min - c.min) < tolerance);
        CHECK(glm::length(b.max - c.max) < tolerance);
        size_t textured = 0, colored = 0;
        for (const Material& m : mesh.materials) textured += m.base_color_map.texture ? 1 : 0;
        for (const MeshPart& p : mesh.parts) colored += p.colors.empty() ? 0 : 1;
        CHECK(textured == c.textured_materials);
        CHECK(colored == c.parts_with_colors);
    }
}

TEST_CASE("assimp's meshes wind outwards with matching normals", "[assets][assimp][real]") {
    if (!have_models()) FACET_SKIP(kNoModels);
    // Cubes: flat faces, normals along them.
    for (const char* file : {"PLY/cube.ply", "FBX/box.fbx", "3DS/cube_with_diffuse_texture.3DS"}) {
        INFO(file);
        require_normals_agree_with_winding(load_mesh(kAssimpModels + file), 0.99f);
    }
    // Wuson.stl's facet normals are zero: they come from its faces, smooth
    // across gentle folds, so on each face's side.
    require_normals_agree_with_winding(load_mesh(kAssimpModels + "STL/Wuson.stl"), 0.0f);
}

TEST_CASE("the same model in PLY, STL and OBJ renders the same", "[assets][assimp][real]") {
    if (!have_models()) FACET_SKIP(kNoModels);
    TempDir dir("assimp");
    const DepthImage obj = depth_of(dir, kAssimpModels + "OBJ/WusonOBJ.obj", "", 1);
    for (const char* file : {"PLY/Wuson.ply", "STL/Wuson.stl"}) {
        INFO(file);
        const DepthImage other = depth_of(dir, kAssimpModels + file, "", 1);
        CHECK(depth_difference(obj, other).first < 0.002);  // coverage
        CHECK(share_of_depth_differences(obj, other, 1e-3f) < 0.005);
    }
}

TEST_CASE("assimp files: missing textures warn, broken files are errors", "[assets][assimp]") {
    if (!have_models()) FACET_SKIP(kNoModels);
    // Absolute paths of the machine that wrote the file: a warning each.
    const Mesh spider = load_mesh(kAssimpModels + "FBX/spider.fbx");
    REQUIRE(!spider.warnings.empty());
    CHECK_THAT(spider.warnings[0].describe(), Catch::Matchers::Contains("spider.fbx") &&
                                                  Catch::Matchers::Contains("drawn without it"));
    // Outside the file's folder: refused by the asset path policy, a warning.
    const Mesh colors = load_mesh(kAssimpModels + "Collada/kwxport_test_vcolors.dae");
    REQUIRE(!colors.warnings.empty());
    CHECK_THAT(colors.warnings[0].describe(), Catch::Matchers::Contains("outside"));
    TempDir dir("assimp");
    require_input_error([&] { load_mesh(write_text(dir.file("empty.stl"), "")); }, "empty.stl");
    require_input_error(
        [&] { load_mesh(write_text(dir.file("lines.stl"), "solid x\nendsolid x\n")); },
        "lines.stl");
    const std::string fbx = read_file(kAssimpModels + "FBX/box.fbx");
    require_input_error(
        [&] { load_mesh(write_text(dir.file("cut.fbx"), fbx.substr(0, fbx.size() / 2))); },
        "cut.fbx");
}

TEST_CASE("PLY files are checked before assimp reads them", "[assets][assimp][untrusted]") {
    // assimp 5.2.5 aborts, crashes or loops on each of these; facet stops
    // with an error naming the file and what is wrong.
    TempDir dir("ply");
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string good = header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    CHECK(load_mesh(write_text(dir.file("good.ply"), good)).triangle_count() == 1);
    struct Case {
        const char* name;
        std::string text;
        const char* message;
    };
    const Case cases[] = {
        {"no end_header", "ply\nformat ascii 1.0\nelement vertex 3\n", "header does not end"},
        {"not PLY", "plx\n", "does not start with 'ply'"},
        {"unknown format", "ply\nformat utf8 1.0\nend_header\n", "unknown format 'utf8'"},
        {"unknown type",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n1\n",
         "unknown type 'real'"},
        {"data cut short", header + "0 0 0\n1 0 0\n", "element 'vertex' ends early"},
        {"face cut short", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "element 'face' ends early"},
        {"index past the vertices", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
         "refers to a vertex past the 3"},
        {"negative list length", header + "0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n", "list length"},
        {"a word for a number", header + "0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n",
         "'zero' where a number belongs"},
        {"a billion vertices declared",
         "ply\nformat ascii 1.0\nelement vertex 1000000000\n"
         "property float x\nend_header\n1\n",
         "more instances than the file holds"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const std::string path = write_text(dir.file("bad.ply"), c.text);
        require_input_error([&] { load_mesh(path); }, c.message);
    }
    // Binary: a face list of 200 items in a file that holds 3, and an index
    // past the vertices.
    std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    binary.append(reinterpret_cast<const char*>(positions), sizeof positions);
    auto with_face = [&](uint8_t count, std::vector<int32_t> indices) {
        std::string text = binary;
        text += static_cast<char>(count);
        text.append(reinterpret_cast<const char*>(indices.data()), indices.size() * 4);
        return write_text(dir.file("binary.ply"), text);
    };
    CHECK(load_mesh(with_face(3, {0, 1, 2})).triangle_count() == 1);
    require_input_error([&] { load_mesh(with_face(200, {0, 1, 2})); }, "element 'face' ends early");
    require_input_error([&] { load_mesh(with_face(3, {0, 1, 1 << 30})); }, "past the 3");
    require_input_error([&] { load_mesh(with_face(3, {0, -1, 2})); }, "past the 3");
}
