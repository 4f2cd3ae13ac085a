// glTF material features beyond the base colour: vertex colours (COLOR_0),
// emission (emissiveFactor with KHR_materials_emissive_strength) and
// KHR_materials_unlit, read from small files built here and checked on the
// rendered, linear colour.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

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

// A unit quad facing +Z (two triangles), with the material `material`.
Gltf quad(const json& material, const std::vector<float>& colors = {}) {
    Gltf g;
    json attributes = {{"POSITION", g.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3")},
                       {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")}};
    if (!colors.empty())
        attributes["COLOR_0"] = g.floats(colors, colors.size() == 12 ? "VEC3" : "VEC4");
    g.doc["materials"] = json::array({material});
    g.one_node_scene({{"attributes", attributes},
                      {"indices", g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, 5123)},
                      {"material", 0}});
    return g;
}

// The linear colour of the quad seen from the front at 64 x 64, with a
// style and a light given as scene YAML.
ColorImage render_quad(const TempDir& dir, Gltf& g, const std::string& style,
                       const std::string& lights = "") {
    const std::string mesh = g.write(dir.file("quad.gltf"));
    const std::string text = "output: { size: [64, 64], frames: \"1\" }\nstyle: " + style +
                             "\ncamera: { position: [0, 0, 3], target: [0, 0, 0], fov: 60 }\n" +
                             lights + "objects:\n  - mesh: " + mesh + "\n";
    return to_float_image(render_frame(load(write_text(dir.file("quad.yaml"), text)), 1).color);
}

glm::vec3 rgb(const ColorImage& image, int x, int y) {
    return glm::vec3(image.at(x, y));
}

const json kWhite = {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}}};

}  // namespace

TEST_CASE("glTF vertex colours multiply the base colour", "[gltf][materials]") {
    TempDir dir("gltf-materials");
    // Corners: red bottom-left, green bottom-right, blue top-right, white top-left.
    const std::vector<float> colors = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    for (const bool with_alpha : {false, true}) {
        INFO("RGBA: " << with_alpha);
        std::vector<float> c = colors;
        if (with_alpha) c = {1, 0, 0, 0.5f, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
        Gltf g = quad(kWhite, c);
        const ColorImage image = render_quad(dir, g, "unlit");
        // Near each corner the corner's colour dominates; the quad fills
        // the middle of the view (about 38 of 64 pixels wide).
        const glm::vec3 bottom_left = rgb(image, 15, 48), bottom_right = rgb(image, 48, 48);
        const glm::vec3 top_right = rgb(image, 48, 15), top_left = rgb(image, 15, 15);
        CHECK(bottom_left.r > 0.8f);
        CHECK(bottom_left.g < 0.2f);
        CHECK(bottom_right.g > 0.8f);
        CHECK(bottom_right.b < 0.2f);
        CHECK(top_right.b > 0.8f);
        CHECK(top_right.r < 0.2f);
        CHECK(glm::all(glm::greaterThan(top_left, glm::vec3(0.8f))));
    }
    // Against a base colour: half red times a yellow vertex colour is half red.
    Gltf g = quad({{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}}}},
                  {1, 1, 0, 1, 1, 0, 1, 1, 0, 1, 1, 0});
    const glm::vec3 centre = rgb(render_quad(dir, g, "unlit"), 32, 32);
    CHECK(centre.r == Approx(0.5f).margin(0.01f));
    CHECK(centre.g == Approx(0.5f).margin(0.01f));
    CHECK(centre.b == Approx(0.0f).margin(0.01f));
}

TEST_CASE("glTF emission adds to the lit colour, scaled by its strength", "[gltf][materials]") {
    TempDir dir("gltf-materials");
    const std::string light =
        "lights:\n  - { type: directional, direction: [0, 0, -1], intensity: 0.5 }\n";
    Gltf plain = quad({{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.2, 0.2, 1}}}}});
    Gltf glowing =
        quad({{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.2, 0.2, 1}}}},
              {"emissiveFactor", {1, 0.5, 0}},
              {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2}}}}}});
    glowing.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const Mesh mesh = load_gltf(glowing.write(dir.file("glowing.gltf")));
    CHECK(mesh.warnings.empty());
    CHECK(mesh.materials[0].emissive == glm::vec3(2, 1, 0));
    for (const char* style : {"phong", "toon", "gooch"}) {
        INFO(style);
        const glm::vec3 a = rgb(render_quad(dir, plain, style, light), 32, 32);
        const glm::vec3 b = rgb(render_quad(dir, glowing, style, light), 32, 32);
        // Half floats: a few thousandths.
        CHECK(b.r - a.r == Approx(2.0f).margin(0.01f));
        CHECK(b.g - a.g == Approx(1.0f).margin(0.01f));
        CHECK(b.b - a.b == Approx(0.0f).margin(0.01f));
    }
    // The normal view is a measurement: emission leaves it alone.
    CHECK(rgb(render_quad(dir, plain, "normals"), 32, 32) ==
          rgb(render_quad(dir, glowing, "normals"), 32, 32));
}

TEST_CASE("KHR_materials_unlit shows the base colour whatever the lights", "[gltf][materials]") {
    TempDir dir("gltf-materials");
    json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}}},
                     {"extensions", {{"KHR_materials_unlit", json::object()}}}};
    for (const std::string light :
         {"lights:\n  - { type: directional, direction: [0, 0, -1], intensity: 3 }\n",
          "lights:\n  - { type: directional, direction: [1, 0, 0.2], intensity: 0.2, color: "
          "[1, 0, 0] }\n"}) {
        INFO(light);
        Gltf g = quad(material);
        g.doc["extensionsUsed"] = {"KHR_materials_unlit"};
        const glm::vec3 c = rgb(render_quad(dir, g, "phong", light), 32, 32);
        CHECK(c.r == Approx(0.2f).margin(0.002f));
        CHECK(c.g == Approx(0.4f).margin(0.002f));
        CHECK(c.b == Approx(0.6f).margin(0.002f));
    }
    // Without the extension the same light changes the colour.
    Gltf lit = quad({{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}}}});
    const glm::vec3 c = rgb(
        render_quad(dir, lit, "phong",
                    "lights:\n  - { type: directional, direction: [0, 0, -1], intensity: 3 }\n"),
        32, 32);
    CHECK(c.r > 0.3f);
}

TEST_CASE("bad emission and vertex colours are errors naming the file", "[gltf][materials]") {
    TempDir dir("gltf-materials");
    Gltf negative = quad({{"emissiveFactor", {-1, 0, 0}}});
    require_input_error([&] { load_gltf(negative.write(dir.file("negative.gltf"))); },
                        "negative.gltf");
    Gltf strength = quad(
        {{"emissiveFactor", {1, 0, 0}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", "bright"}}}}}});
    require_input_error([&] { load_gltf(strength.write(dir.file("strength.gltf"))); },
                        "emissiveStrength");
    Gltf short_colors = quad(kWhite, {1, 0, 0, 0, 1, 0, 0, 0, 1});  // three of four vertices
    require_input_error([&] { load_gltf(short_colors.write(dir.file("colors.gltf"))); }, "COLOR_0");
}

TEST_CASE("scene materials set emission and unlit", "[scene][materials]") {
    TempDir dir("gltf-materials");
    Gltf g = quad(kWhite);
    const std::string mesh = g.write(dir.file("quad.gltf"));
    const SceneDesc scene = load(write_text(
        dir.file("scene.yaml"), "objects:\n  - mesh: " + mesh +
                                    "\n    material: { emissive: [0, 0.5, 0], unlit: true }\n"));
    const World world = build_world(scene);
    CHECK(world.materials[0].emissive == glm::vec3(0, 0.5f, 0));
    CHECK(world.materials[0].unlit);
    require_input_error(
        [&] {
            load(write_text(dir.file("bad.yaml"),
                            "objects:\n  - mesh: " + mesh + "\n    material: { unlit: 3 }\n"));
        },
        "unlit");
}
