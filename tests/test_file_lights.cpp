// KHR_lights_punctual: an object with `lights:` brings its glTF file's
// lights into the scene, placed by their nodes and moved with the object;
// without it they are not used.
#include <catch2/catch.hpp>

#include <cmath>

#include "asset_support.hpp"
#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "real_asset_support.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

// A quad facing +Z at the origin, and a light on a node two units in front
// of it, turned (for spots and suns) to shine down -Z onto it.
std::string lit_file(const TempDir& dir, const json& light, const std::string& name) {
    Gltf g;
    const int quad =
        g.mesh({{"attributes",
                 {{"POSITION", g.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3")},
                  {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")}}},
                {"indices", g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, 5123)}});
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    g.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({light})}}}};
    const int shown = g.node({{"name", "Quad"}, {"mesh", quad}});
    const int lamp = g.node({{"name", "Lamp"},
                             {"translation", {0, 0, 2}},
                             {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    g.scene({shown, lamp});
    return g.write(dir.file(name));
}

// The linear red of the quad's centre, seen from the front, with no scene lights.
float centre_red(const TempDir& dir, const std::string& file, const std::string& object_extra) {
    const SceneDesc scene =
        load(write_text(dir.file("lit.yaml"),
                        "output: { size: [32, 32], frames: \"1\" }\nstyle: lit\nlights: []\n"
                        "camera: { position: [0, 0, 4], target: [0, 0, 0], fov: 50 }\n"
                        "objects:\n  - mesh: " +
                            file + "\n    material: { ambient: 0, specular: 0 }\n" + object_extra));
    return to_float_image(render_frame(scene, 1).color).at(16, 16).r;
}

}  // namespace

TEST_CASE("glTF point lights light their object when it asks for them", "[gltf][lights]") {
    TempDir dir("file-lights");
    const std::string file = lit_file(
        dir, {{"type", "point"}, {"color", {1, 1, 1}}, {"intensity", 4 * M_PI}}, "point.gltf");
    const Mesh mesh = load_gltf(file);
    REQUIRE(mesh.lights.size() == 1);
    CHECK(mesh.lights[0].name == "Lamp");
    CHECK(mesh.lights[0].position == glm::vec3(0, 0, 2));
    CHECK(mesh.warnings.empty());
    // Not asked for: no light at all.
    CHECK(centre_red(dir, file, "") == Approx(0).margin(1e-3));
    // 4π candela at distance 2: 4π / 2² = π lux, which facet lights as
    // π / π = 1 (kGltfLightUnit), times the diffuse 0.8 (white quad).
    const float lit = centre_red(dir, file, "    lights: true\n");
    CHECK(lit == Approx(0.8f).epsilon(0.01));
    // Scaled.
    CHECK(centre_red(dir, file, "    lights: { intensity: 0.5 }\n") ==
          Approx(lit * 0.5f).epsilon(0.01));
    // Moved with the object: one unit back, the light is still 2 from the
    // quad (left behind it would be 3 away: 4/9 of the light).
    CHECK(centre_red(dir, file, "    lights: true\n    translate: [0, 0, -1]\n") ==
          Approx(lit).epsilon(0.01));
}

TEST_CASE("glTF spot and directional lights shine down their node's -Z", "[gltf][lights]") {
    TempDir dir("file-lights");
    const std::string spot =
        lit_file(dir,
                 {{"type", "spot"},
                  {"intensity", 4 * M_PI},
                  {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.4}}}},
                 "spot.gltf");
    const Mesh mesh = load_gltf(spot);
    REQUIRE(mesh.lights.size() == 1);
    CHECK(mesh.lights[0].type == GltfLight::Type::spot);
    CHECK(mesh.lights[0].direction == glm::vec3(0, 0, -1));
    CHECK(mesh.lights[0].outer_degrees == Approx(0.4 * 180 / M_PI));
    CHECK(centre_red(dir, spot, "    lights: true\n") == Approx(0.8f).epsilon(0.01));
    const std::string sun =
        lit_file(dir, {{"type", "directional"}, {"intensity", 0.5 * M_PI}}, "sun.gltf");
    CHECK(centre_red(dir, sun, "    lights: true\n") == Approx(0.4f).epsilon(0.01));
}

TEST_CASE("glTF light errors name the file, the light and the key", "[gltf][lights][errors]") {
    TempDir dir("file-lights");
    require_input_error(
        [&] {
            load_gltf(lit_file(dir, {{"type", "area"}}, "area.gltf"));
        },
        "unknown type 'area'");
    require_input_error(
        [&] {
            load_gltf(lit_file(dir, {{"type", "point"}, {"intensity", -1}}, "negative.gltf"));
        },
        "negative.gltf: light 'Lamp'");
    require_input_error(
        [&] {
            load_gltf(lit_file(
                dir,
                {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.2}}}},
                "cone.gltf"));
        },
        "spot cone angles");
    require_input_error(
        [&] {
            load(write_text(dir.file("prim.yaml"),
                            "objects:\n  - primitive: cube\n    lights: true\n"));
        },
        "only glTF meshes carry lights");
}
