// glTF 2.0 loading (src/assets/gltf_loader.cpp) of the real sample and broken
// files among assimp's test models.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"

namespace fs = std::filesystem;
using namespace facet::test;
using nlohmann::json;

namespace {

const std::string kGltfDir = kAssimpModels + "glTF2/";

// The size in a PNG's IHDR, read directly from its bytes.
std::pair<int, int> png_size(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char h[24] = {};
    in.read(reinterpret_cast<char*>(h), 24);
    auto be = [&](int at) {
        return (h[at] << 24) | (h[at + 1] << 16) | (h[at + 2] << 8) | h[at + 3];
    };
    return {be(16), be(20)};
}

}  // namespace

TEST_CASE("glTF real BoxTextured in all three containers", "[assets][gltf][real]") {
    auto [tw, th] = png_size(kGltfDir + "BoxTextured-glTF/CesiumLogoFlat.png");
    REQUIRE(tw == 211);
    // The texture coordinates' range, as the file's own accessor states it
    // (they run past 1 to repeat the logo).
    std::ifstream in(kGltfDir + "BoxTextured-glTF/BoxTextured.gltf");
    json doc = json::parse(in);
    const json& uv_accessor =
        doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"].get<int>()];
    const glm::vec2 uv_min(uv_accessor["min"][0].get<float>(), uv_accessor["min"][1].get<float>());
    const glm::vec2 uv_max(uv_accessor["max"][0].get<float>(), uv_accessor["max"][1].get<float>());
    REQUIRE(uv_max.x > uv_min.x);
    for (const std::string rel :
         {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
          "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        DYNAMIC_SECTION(rel) {
            facet::Mesh mesh = facet::load_mesh(kGltfDir + rel);
            check_sane(mesh);
            CHECK(mesh.triangle_count() == 12);
            require_bounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
            require_closed_and_oriented(mesh);
            CHECK(total_area(mesh) == Approx(6.0f));
            require_normals_agree_with_winding(mesh, 0.99f);
            for (const auto& part : mesh.parts) {
                const auto& m = material_of(mesh, part);
                CHECK(m.name == "Texture");
                REQUIRE(m.base_color_map.texture != nullptr);
                CHECK(m.base_color_map.texture->width == tw);
                CHECK(m.base_color_map.texture->height == th);
                CHECK(part.uvs.size() == part.positions.size());
                glm::vec2 lo(1e30f), hi(-1e30f);
                for (const auto& uv : part.uvs) {
                    lo = glm::min(lo, uv);
                    hi = glm::max(hi, uv);
                }
                CHECK(lo.x == Approx(uv_min.x));
                CHECK(lo.y == Approx(uv_min.y));
                CHECK(hi.x == Approx(uv_max.x));
                CHECK(hi.y == Approx(uv_max.y));
            }
        }
    }
}

TEST_CASE("glTF real 2CylinderEngine flattens its node hierarchy", "[assets][gltf][real]") {
    // Expected values computed independently from the file with a small
    // Python reader (sum of index counts / 3 over every mesh instance reached
    // from the scene; world-space bounds of the transformed vertices).
    facet::Mesh mesh =
        facet::load_gltf(kGltfDir + "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 121496);
    require_bounds(mesh, {-371.69226f, -180.97156f, -139.99999f}, {371.69217f, 92.04156f, 128.0f},
                   0.01f);
    CHECK(mesh.materials.size() >= 34);
}

TEST_CASE("glTF real broken files are errors, not crashes", "[assets][gltf][real]") {
    for (const std::string rel :
         {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
          "IndexOutOfRange/IndexOutOfRange.gltf", "IndexOutOfRange/AllIndicesOutOfRange.gltf",
          "MissingBin/BoxTextured.gltf", "RecursiveNodes/RecursiveNodes.gltf",
          "TestNoRootNode/NoScene.gltf", "TestNoRootNode/SceneWithoutNodes.gltf"}) {
        DYNAMIC_SECTION(rel) {
            require_input_error([&] { facet::load_mesh(kGltfDir + rel); },
                                fs::path(rel).filename().string());
        }
    }
}

TEST_CASE("glTF real BoxBadNormals: bad normals become usable ones", "[assets][gltf][real]") {
    // Four normals are (0,0,0) and four are (0,-0.1,0): neither is unit length.
    facet::Mesh mesh = facet::load_gltf(kGltfDir + "BoxBadNormals-glTF-Binary/BoxBadNormals.glb");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 12);
    require_bounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
    require_normals_agree_with_winding(mesh, 0.99f);
}

TEST_CASE("glTF real IncorrectVertexArrays drops incomplete triangles", "[assets][gltf][real]") {
    // Cube (36 vertices) 12, TruncatedCube (35) 11, IndexedCube 12,
    // TruncatedIndexedCube (35 indices) 11; the four line meshes give none.
    facet::Mesh mesh = facet::load_gltf(kGltfDir + "IncorrectVertexArrays/Cube.gltf");
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 46);
    require_bounds(mesh, {-3.5f, -1, -1}, {3.5f, 1, 3.5f}, 1e-4f);
}

TEST_CASE("glTF real small scenes", "[assets][gltf][real]") {
    SECTION("simple_skin: the bind pose, animation listed") {
        facet::Mesh mesh = facet::load_gltf(kGltfDir + "simple_skin/simple_skin.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 8);
        // The skin at rest: both inverse bind matrices shift by -0.5 in x.
        require_bounds(mesh, {-0.5f, 0, 0}, {0.5f, 2, 0});
        REQUIRE(mesh.rig != nullptr);
        CHECK(mesh.rig->animations.size() == 1);
    }
    SECTION("cameras: rotated square, cameras ignored") {
        facet::Mesh mesh = facet::load_gltf(kGltfDir + "cameras/Cameras.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 2);
        require_bounds(mesh, {0, 0, -0.70759f}, {1, 0.70662f, 0}, 1e-4f);
    }
    SECTION("textureTransform: nine textured squares") {
        facet::Mesh mesh =
            facet::load_gltf(kGltfDir + "textureTransform/TextureTransformTest.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 24);
        require_bounds(mesh, {-1.6f, -1.14127f, 0}, {1.6f, 1.05f, 0.01f}, 1e-4f);
        for (const auto& part : mesh.parts)
            CHECK(material_of(mesh, part).base_color_map.texture != nullptr);
    }
    SECTION("BoxTexcoords: two texture coordinate sets") {
        facet::Mesh mesh = facet::load_gltf(kGltfDir + "BoxTexcoords-glTF/boxTexcoords.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 12);
        require_bounds(mesh, glm::vec3(-1), glm::vec3(1));
    }
    SECTION("AnimatedMorphCube: base shape and its animation name") {
        facet::Mesh mesh = facet::load_gltf(
            kGltfDir + "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 12);
        REQUIRE(mesh.rig != nullptr);
        REQUIRE(mesh.rig->animations.size() == 1);
        CHECK(mesh.rig->animations[0].name == "Square");
    }
}

// Each file is BoxTextured with one field of the wrong JSON type. A field
// facet draws from is refused, naming it; a name (not drawn) is not read.
TEST_CASE("glTF real wrongTypes files: a wrong type where facet reads is refused",
          "[assets][gltf][real]") {
    const std::string dir = kGltfDir + "wrongTypes/";
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"badArray.gltf", "meshes[0].primitives must be a list"},
        {"badExtension.gltf",
         "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform "
         "must be an object"},
        {"badNumber.gltf", "materials[0].normalTexture.index must be present"},
        {"badObject.gltf", "materials[0].pbrMetallicRoughness must be an object"},
        {"badUint.gltf",
         "materials[0].pbrMetallicRoughness.baseColorTexture.index must be an "
         "index (a whole number from 0 to 2147483647), not -1"}};
    for (const auto& file : refused) DYNAMIC_SECTION(file.first) {
            require_input_error([&] { facet::load_gltf(dir + file.first); }, file.second);
        }
    SECTION("badString.gltf: a scene's name, which facet does not read") {
        const facet::Mesh mesh = facet::load_gltf(dir + "badString.gltf");
        check_sane(mesh);
        CHECK(mesh.triangle_count() == 12);
        CHECK(mesh.warnings.empty());
    }
}

TEST_CASE("glTF real Asset-Generator primitive modes", "[assets][gltf][real]") {
    // Mesh_PrimitiveMode_NN: a unit square at z = 0 drawn with mode N.
    // 00-03 and 07-10 are points, lines, line loops and line strips: nothing to
    // render. The others are two counter-clockwise triangles facing +Z.
    const std::string dir = kGltfDir + "glTF-Asset-Generator/Mesh_PrimitiveMode/";
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".gltf") continue;
        ++files;
        const std::string name = entry.path().filename().string();
        const int number = std::stoi(name.substr(name.size() - 7, 2));
        DYNAMIC_SECTION(name) {
            const bool lines_or_points = number <= 3 || (number >= 7 && number <= 10);
            if (lines_or_points) {
                require_input_error([&] { facet::load_gltf(entry.path().string()); }, name);
            } else {
                facet::Mesh mesh = facet::load_gltf(entry.path().string());
                check_sane(mesh);
                CHECK(mesh.triangle_count() == 2);
                CHECK(total_area(mesh) == Approx(1.0f));
                require_bounds(mesh, {-0.5f, -0.5f, 0}, {0.5f, 0.5f, 0});
                for (const auto& part : mesh.parts)
                    for (size_t t = 0; t < part.triangle_count(); ++t)
                        CHECK(face_cross(part, t).z > 0);
                require_normals_agree_with_winding(mesh, 0.99f);
            }
        }
    }
    CHECK(files == 16);
}

// Every glTF file of assimp's test models, each with its expected outcome:
// the files below are refused (glTF 1.0, broken on purpose, or with nothing
// to draw), and every other one loads sanely.
TEST_CASE("glTF every real file loads sanely, or is refused as expected", "[assets][gltf][real]") {
    const std::map<std::string, std::string> refused = {
        {"glTF/BoxTextured-glTF-Binary/BoxTextured.glb", "glTF 1.0 binary"},
        {"glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf", "is glTF 1.0"},
        {"glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf", "is glTF 1.0"},
        {"glTF/BoxTextured-glTF/BoxTextured.gltf", "is glTF 1.0"},
        {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "as glTF 1.0 did"},
        {"glTF/IncorrectVertexArrays/Cube_v1.gltf", "is glTF 1.0"},
        {"glTF/TwoBoxes/TwoBoxes.gltf", "is glTF 1.0"},
        {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf",
         "requires the glTF extension KHR_technique_webgl"},
        {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "not finite"},
        {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "index 65535 is out of range"},
        {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "index 255 is out of range"},
        {"glTF2/MissingBin/BoxTextured.gltf", "no such file"},
        {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "cycle through node 0"},
        {"glTF2/SchemaFailures/sceneWrongType.gltf", "scene must be an index"},
        {"glTF2/TestNoRootNode/NoScene.gltf", "no triangles"},
        {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", "no triangles"},
    };
    std::vector<std::string> names;
    for (const std::string root : {"glTF2", "glTF"})
        for (const auto& entry : fs::recursive_directory_iterator(kAssimpModels + root)) {
            const auto ext = entry.path().extension();
            const std::string name = fs::relative(entry.path(), kAssimpModels).string();
            // Each of these folders has its own test, file by file.
            const bool own_test = name.find("/wrongTypes/") != std::string::npos ||
                                  name.find("/Mesh_PrimitiveMode/") != std::string::npos;
            if ((ext == ".gltf" || ext == ".glb") && !own_test) names.push_back(name);
        }
    std::sort(names.begin(), names.end());
    REQUIRE(names.size() > 25);
    for (const auto& [name, message] : refused)
        CHECK(std::find(names.begin(), names.end(), name) != names.end());
    for (const auto& name : names) {
        DYNAMIC_SECTION(name) {
            const auto expected = refused.find(name);
            if (expected != refused.end())
                require_input_error([&] { facet::load_mesh(kAssimpModels + name); },
                                    expected->second);
            else
                check_sane(facet::load_mesh(kAssimpModels + name));
        }
    }
}
