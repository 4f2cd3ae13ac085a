// STL, FBX, Collada and 3DS through libassimp (assets/assimp_loader.cpp),
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
    if (std::filesystem::exists(kAssimpModels + "STL/Wuson.stl")) return true;
    WARN("skipped: " << kAssimpModels << " is missing (install assimp-testmodels)");
    return false;
}

struct FormatCase {
    const char* file;  // under kAssimpModels
    size_t triangles;
    glm::vec3 min, max;  // bounds, to 1e-3 of the size
    size_t textured_materials;
    size_t parts_with_colors;
};

}  // namespace

TEST_CASE("assimp reads STL, FBX, Collada and 3DS files", "[assets][assimp][real]") {
    if (!have_models()) return;
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
        for (const Material& m : mesh.materials) textured += m.texture ? 1 : 0;
        for (const MeshPart& p : mesh.parts) colored += p.colors.empty() ? 0 : 1;
        CHECK(textured == c.textured_materials);
        CHECK(colored == c.parts_with_colors);
    }
}

TEST_CASE("assimp's closed cubes wind outwards with matching normals", "[assets][assimp][real]") {
    if (!have_models()) return;
    for (const char* file : {"FBX/box.fbx", "3DS/cube_with_diffuse_texture.3DS"}) {
        INFO(file);
        const Mesh mesh = load_mesh(kAssimpModels + file);
        require_normals_agree_with_winding(mesh, 0.99f);
    }
}

TEST_CASE("the same model in STL and OBJ renders the same", "[assets][assimp][real]") {
    if (!have_models()) return;
    TempDir dir("assimp");
    const DepthImage obj = depth_of(dir, kAssimpModels + "OBJ/WusonOBJ.obj", "", 1);
    for (const char* file : {"STL/Wuson.stl"}) {
        INFO(file);
        const auto [coverage, depth] =
            depth_difference(obj, depth_of(dir, kAssimpModels + file, "", 1));
        CHECK(coverage < 0.002);
        CHECK(depth < 1e-3);
    }
}

TEST_CASE("assimp files: missing textures warn, broken files are errors", "[assets][assimp]") {
    if (!have_models()) return;
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
    // PLY waits for a check of its own (assimp's reader loops on this one).
    require_input_error(
        [&] {
            load_mesh(write_text(dir.file("cut.ply"), "ply\nformat ascii 1.0\nelement vertex 3\n"));
        },
        "unsupported mesh format '.ply'");
    require_input_error(
        [&] { load_mesh(write_text(dir.file("lines.stl"), "solid x\nendsolid x\n")); },
        "lines.stl");
    const std::string fbx = read_file(kAssimpModels + "FBX/box.fbx");
    require_input_error(
        [&] { load_mesh(write_text(dir.file("cut.fbx"), fbx.substr(0, fbx.size() / 2))); },
        "cut.fbx");
}
