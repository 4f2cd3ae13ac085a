// glTF animation, skinning and morph targets on real files from assimp's
// test models (Debian's assimp-testmodels). The expected values are worked
// out from the files' own JSON, quoted in the comments.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/gltf_pose.hpp"
#include "gltf_anim_support.hpp"

using namespace facet::test;
using facet::Mesh;
using nlohmann::json;

namespace {

const std::string kSimpleSkin = kAssimpModels + "glTF2/simple_skin/simple_skin.gltf";
const std::string kMorphCube =
    kAssimpModels + "glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf";

// The test models are a separate package; without it these tests are
// reported skipped (FACET_SKIP).
bool have_file(const std::string& path) {
    return std::filesystem::is_regular_file(path);
}

const char* const kNoModels = "assimp-testmodels is missing (scripts/setup.sh --tests installs it)";

json read_json(const std::string& path) {
    std::ifstream in(path);
    return json::parse(in);
}

}  // namespace

TEST_CASE("glTF real simple_skin bends its upper half", "[gltf][anim][skin][real]") {
    if (!have_file(kSimpleSkin)) FACET_SKIP(kNoModels);
    Mesh mesh = facet::load_gltf(kSimpleSkin);
    REQUIRE(facet::animation_count(mesh) == 1);
    // Input accessor 5: 12 keys, "max": [5.5].
    CHECK(facet::animation_duration(mesh, 0) == 5.5);
    CHECK(facet::find_animation(mesh, "animation0") == 0);
    const auto& part = mesh.parts[0];

    // Both joints (nodes 1 and 2) sit at (0, 1) at rest, and both inverse
    // bind matrices translate by (-0.5, -1): every joint matrix is a shift
    // by -0.5 in x, and so is the whole mesh. The loaded parts are that
    // rest pose already (the skin at rest, §3.7.3.3), and time 0 is it.
    auto start = posed(mesh, 0, 0);
    for (size_t v = 0; v < part.positions.size(); ++v) {
        require_vec3(start[0].positions[v], part.positions[v]);
        CHECK(std::abs(start[0].normals[v].z) == Approx(1));
    }
    CHECK(mesh.bounds().min.x == Approx(-0.5f));  // the file's x from 0, shifted
    // Node 2's rotation reaches (0, 0, 0.707, 0.707), a quarter turn about
    // +Z, at t = 1 and holds to 1.5; at 4 and 4.5 it is the opposite turn.
    // Vertices at y = 2 hang on joint 1 alone: (x, 2) at rest turned about
    // the joint at (0, 1). Vertices at y = 0 hang on joint 0.
    for (auto [t, turn] : std::vector<std::pair<double, double>>{{1.5, 1}, {4.5, -1}}) {
        INFO("t = " << t);
        auto parts = posed(mesh, 0, t);
        int top = 0;
        for (size_t v = 0; v < part.positions.size(); ++v) {
            const glm::vec3 rest = part.positions[v];
            if (rest.y == 2) {
                ++top;
                require_vec3(parts[0].positions[v],
                             {static_cast<float>(-turn), static_cast<float>(1 + turn * rest.x), 0},
                             1e-5f);
            } else if (rest.y == 0) {
                require_vec3(parts[0].positions[v], rest);
            }
        }
        CHECK(top >= 2);
        facet::Bounds b = bounds_of(parts);
        CHECK(b.min.x == Approx(turn > 0 ? -1 : -0.5).margin(1e-5));
        CHECK(b.max.x == Approx(turn > 0 ? 0.5 : 1).margin(1e-5));
    }
}

TEST_CASE("glTF real AnimatedMorphCube morphs its top face", "[gltf][anim][morph][real]") {
    if (!have_file(kMorphCube)) FACET_SKIP(kNoModels);
    const json doc = read_json(kMorphCube);
    Mesh mesh = facet::load_gltf(kMorphCube);
    REQUIRE(facet::animation_count(mesh) == 1);
    const double last_key = doc["accessors"][10]["max"][0].get<double>();  // 4.19999743
    CHECK(facet::animation_duration(mesh, 0) == Approx(last_key).epsilon(1e-7));
    const auto& part = mesh.parts[0];

    // The weights start at (0, 0): the pose is the bake, to the bit.
    auto start = posed(mesh, 0, 0);
    CHECK(start[0].positions == part.positions);
    CHECK(start[0].normals == part.normals);

    // Node 0 turns the mesh by its rotation, a half turn that takes mesh
    // (x, y, z) to (-x, -z, -y), and scales it by 100. Both targets lift
    // vertices in mesh +Y, by their accessors' "max": "thin" (accessor 4)
    // every vertex of the bottom face (mesh y = -0.01, world z = +1) up
    // through the top, flattening the cube; "angle" (accessor 7) only the
    // bottom's back edge (also mesh z = -0.01, world y = +1).
    const json& node = doc["nodes"][0];
    const glm::dquat rotation(node["rotation"][3].get<double>(), node["rotation"][0].get<double>(),
                              node["rotation"][1].get<double>(), node["rotation"][2].get<double>());
    const glm::dvec3 up = rotation * glm::dvec3(0, 1, 0) * node["scale"][0].get<double>();
    require_vec3(glm::vec3(up), {0, 0, -100}, 1e-3f);
    struct Moment {
        double t;
        int accessor;    // the target whose weight is 1 then
        bool edge_only;  // lifts only vertices at world y = +1 too
    };
    // The weights are (1, 0) at t = 1.6 and (0, 1) at t = 3.4 (keys 48 and 102).
    for (const Moment m : {Moment{1.6, 4, false}, Moment{3.4, 7, true}}) {
        INFO("t = " << m.t);
        const double lift = doc["accessors"][m.accessor]["max"][1].get<double>();
        const glm::vec3 moved = glm::vec3(up * lift);
        auto parts = posed(mesh, 0, m.t);
        for (size_t v = 0; v < part.positions.size(); ++v) {
            const glm::vec3 rest = part.positions[v];
            const bool lifted = rest.z > 0.99f && (!m.edge_only || rest.y > 0.99f);
            INFO("vertex " << v);
            require_vec3(parts[0].positions[v] - rest, lifted ? moved : glm::vec3(0), 1e-3f);
            CHECK(glm::length(parts[0].normals[v]) == Approx(1).margin(1e-5));
        }
        // Posing is a pure function: the same call gives the same bits.
        CHECK(posed(mesh, 0, m.t)[0].positions == parts[0].positions);
    }
    // Flattened: the bottom, once at world z = +1, now lies near the top at z = -1.
    const float thin_lift = doc["accessors"][4]["max"][1].get<float>();
    CHECK(bounds_of(posed(mesh, 0, 1.6)).max.z == Approx(1 - 100 * thin_lift).margin(1e-3));
    CHECK(mesh.bounds().max.z == Approx(1).margin(1e-5));
}

TEST_CASE("facet info lists animations, skins and morph targets", "[gltf][anim][real][cli]") {
    if (!have_file(kSimpleSkin) || !have_file(kMorphCube)) FACET_SKIP(kNoModels);
    auto skin = run_facet("info '" + kSimpleSkin + "'");
    INFO(skin.output);
    REQUIRE(skin.exit_code == 0);
    CHECK_THAT(skin.output,
               Catch::Contains("animations: 1\n  - animation0: 5.5 s, 1 channel, drives node2\n"));
    CHECK_THAT(skin.output, Catch::Contains("skins:      1\n"));
    CHECK_THAT(skin.output, Catch::Contains("morphed:    0 of 1 parts"));
    auto cube = run_facet("info '" + kMorphCube + "'");
    INFO(cube.output);
    REQUIRE(cube.exit_code == 0);
    CHECK_THAT(cube.output,
               Catch::Contains("  - Square: 4.2 s, 1 channel, drives AnimatedMorphCube\n"));
    CHECK_THAT(cube.output, Catch::Contains("skins:      0\n"));
    CHECK_THAT(cube.output, Catch::Contains("morphed:    1 of 1 parts, up to 2 targets\n"));
}
