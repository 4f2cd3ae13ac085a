// facet::load_scene: valid scene files become the right records; every
// invalid one throws facet::Error (exit code 2) naming the file, the line and
// column of the offending text, and the dotted key (shared/design.md §2).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/scene_desc.hpp"
#include "support.hpp"

using Catch::Contains;
using facet::ExitCode;
using facet::Override;
using facet::SceneDesc;
using facet::SceneOptions;
using facet::test::TempDir;
using facet::test::write_text;

namespace {

// "line:column" (1-based) of the first occurrence of `needle` in `text`,
// plus `offset` characters; counted here from the text itself.
std::string line_col(const std::string& text, const std::string& needle, size_t offset = 0) {
    size_t at = text.find(needle);
    REQUIRE(at != std::string::npos);
    at += offset;
    int line = 1, column = 1;
    for (size_t i = 0; i < at; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

SceneOptions with_styles() {
    SceneOptions options;
    options.style_dirs = {FACET_STYLES_DIR};
    return options;
}

SceneDesc load(const std::string& path, SceneOptions options = with_styles()) {
    return facet::load_scene(path, options);
}

// Loads the scene, expecting an invalid-input error; returns its message.
std::string load_error(const std::string& path, const SceneOptions& options = with_styles()) {
    try {
        facet::load_scene(path, options);
    } catch (const facet::Error& e) {
        CHECK(e.code() == ExitCode::invalid_input);
        return e.what();
    }
    FAIL("load_scene accepted " << path);
    return {};
}

// The error must name file:line:column and the key (quoted, as the message writes it).
void check_error_at(const std::string& message, const std::string& file, const std::string& where,
                    const std::string& key) {
    INFO("message: " << message);
    CHECK_THAT(message, Contains(file + ":" + where + ":"));
    if (!key.empty()) CHECK_THAT(message, Contains("'" + key + "'"));
}

bool close_to(float a, float b, float eps = 1e-5f) {
    return std::fabs(a - b) <= eps;
}

// sRGB -> linear, the standard IEC 61966-2-1 formula, written out here so the
// test does not borrow the parser's.
float srgb_byte_to_linear(int byte) {
    double c = byte / 255.0;
    return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

const char* kMinimalObjects = "objects:\n  - primitive: cube\n";

}  // namespace

// ---------------------------------------------------------------------------
// Valid scenes

TEST_CASE("a minimal scene gets the documented defaults", "[scene]") {
    TempDir dir("scene");
    std::string path = write_text(dir.file("minimal.yaml"), kMinimalObjects);
    SceneDesc scene = load(path);
    CHECK(scene.path == path);
    CHECK(scene.name == "minimal");
    CHECK(std::filesystem::equivalent(scene.directory, dir.path()));
    CHECK(scene.output.width == 1280);
    CHECK(scene.output.height == 720);
    CHECK(scene.output.frames == std::vector<int>{1});
    CHECK(scene.output.write_color);
    CHECK_FALSE(scene.output.write_depth);
    CHECK(scene.output.write_png);
    CHECK_FALSE(scene.output.write_exr);
    CHECK(scene.style.name == "default");
    CHECK(scene.camera.fov == 45);
    CHECK_FALSE(scene.camera.orbit.has_value());
    CHECK(scene.lights.empty());
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].name == "object0");
    REQUIRE(scene.objects[0].primitive.has_value());
    CHECK(scene.objects[0].primitive->type == "cube");
    CHECK(scene.objects[0].mesh.empty());
    CHECK(scene.objects[0].scale == glm::vec3(1));
    CHECK(scene.objects[0].visible);
    CHECK_FALSE(scene.objects[0].spin.has_value());
}

TEST_CASE("a full scene parses into the right values", "[scene]") {
    TempDir dir("scene");
    write_text(dir.file("models/tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write_text(dir.file("textures/wood.png"), "not decoded by the scene parser");
    const std::string text = R"(output:
  size: [320, 200]
  frames: 1-10:3
  fps: 30
  passes: [color, depth]
  formats: exr
  background: "#ff8000"
  png_compression: 9
  depth_range: [0.5, 20]
style:
  shading: phong
  description: test look
camera:
  position: [1, 2, 3]
  target: [0, 0.5, 0]
  up: [0, 0, 1]
  fov: 60
  near: 0.5
  far: 50
  orbit:
    center: [1, 0, -1]
    radius: 7.5
    elevation: 30
    start_angle: 90
    turns: -2
lights:
  - type: directional
    direction: [0, -1, -1]
    color: [1, 0.5, 0.25]
    intensity: 2
  - type: point
    position: [3, 4, 5]
objects:
  - name: box
    primitive: cube
    translate: [1, 2, 3]
    rotate: [10, 20, 30]
    scale: 2
    material:
      color: [0.8, 0.1, 0.1]
      ambient: 0.2
      diffuse: 0.7
      specular: 0.5
      shininess: 64
      texture: textures/wood.png
      wrap: clamp
      double_sided: yes
    spin:
      axis: x
      turns: 3
  - name: ball
    primitive:
      type: sphere
      radius: 0.75
      segments: 24
      rings: 12
    scale: [1, 2, 3]
    visible: false
  - mesh: models/tri.obj
    spin:
      axis: [0, 0, 2]
)";
    std::string path = write_text(dir.file("full.yaml"), text);
    SceneDesc scene = load(path);

    const auto& out = scene.output;
    CHECK(out.width == 320);
    CHECK(out.height == 200);
    CHECK(out.frames == std::vector<int>{1, 4, 7, 10});
    CHECK(out.frames_text == "1-10:3");
    CHECK(out.fps == 30);
    CHECK(out.write_color);
    CHECK(out.write_depth);
    CHECK_FALSE(out.write_png);
    CHECK(out.write_exr);
    // #ff8000 in sRGB: red 1, green 128/255 -> 0.2158605 linear, blue 0.
    CHECK(close_to(out.background.r, 1.0f));
    CHECK(close_to(out.background.g, 0.2158605f));
    CHECK(close_to(out.background.b, 0.0f));
    CHECK(close_to(out.background.a, 1.0f));
    CHECK(out.png_compression == 9);
    REQUIRE(out.depth_range.has_value());
    CHECK(*out.depth_range == glm::vec2(0.5f, 20.0f));

    CHECK(scene.style.name == "inline");
    CHECK(scene.style.shading == facet::ShadingModel::phong);
    CHECK(scene.style.description == "test look");

    const auto& cam = scene.camera;
    CHECK(cam.position == glm::vec3(1, 2, 3));
    CHECK(cam.target == glm::vec3(0, 0.5f, 0));
    CHECK(cam.up == glm::vec3(0, 0, 1));
    CHECK(cam.fov == 60);
    CHECK(cam.near == 0.5f);
    CHECK(cam.far == 50);
    REQUIRE(cam.orbit.has_value());
    CHECK(cam.orbit->center == glm::vec3(1, 0, -1));
    CHECK(cam.orbit->radius == 7.5f);
    CHECK(cam.orbit->elevation == 30);
    CHECK(cam.orbit->start_angle == 90);
    CHECK(cam.orbit->turns == -2);

    REQUIRE(scene.lights.size() == 2);
    CHECK(scene.lights[0].type == facet::LightType::directional);
    CHECK(scene.lights[0].direction == glm::vec3(0, -1, -1));
    CHECK(scene.lights[0].color == glm::vec3(1, 0.5f, 0.25f));
    CHECK(scene.lights[0].intensity == 2);
    CHECK(scene.lights[1].type == facet::LightType::point);
    CHECK(scene.lights[1].position == glm::vec3(3, 4, 5));
    CHECK(scene.lights[1].intensity == 1);
    CHECK(scene.lights[1].color == glm::vec3(1, 1, 1));

    REQUIRE(scene.objects.size() == 3);
    const auto& box = scene.objects[0];
    CHECK(box.name == "box");
    REQUIRE(box.primitive.has_value());
    CHECK(box.primitive->type == "cube");
    CHECK(box.translate == glm::vec3(1, 2, 3));
    CHECK(box.rotate == glm::vec3(10, 20, 30));
    CHECK(box.scale == glm::vec3(2, 2, 2));  // a number scales every axis
    REQUIRE(box.material.color.has_value());
    CHECK(*box.material.color == glm::vec3(0.8f, 0.1f, 0.1f));
    CHECK(box.material.ambient == 0.2f);
    CHECK(box.material.diffuse == 0.7f);
    CHECK(box.material.specular == 0.5f);
    CHECK(box.material.shininess == 64.0f);
    REQUIRE(box.material.texture.has_value());
    CHECK(std::filesystem::equivalent(*box.material.texture, dir.file("textures/wood.png")));
    CHECK(box.material.wrap == facet::TextureWrap::clamp);
    CHECK(box.material.double_sided == true);
    REQUIRE(box.spin.has_value());
    CHECK(box.spin->axis == glm::vec3(1, 0, 0));
    CHECK(box.spin->turns == 3);

    const auto& ball = scene.objects[1];
    CHECK(ball.name == "ball");
    REQUIRE(ball.primitive.has_value());
    CHECK(ball.primitive->type == "sphere");
    CHECK(ball.primitive->radius == 0.75f);
    CHECK(ball.primitive->segments == 24);
    CHECK(ball.primitive->rings == 12);
    CHECK(ball.scale == glm::vec3(1, 2, 3));  // a list scales per axis
    CHECK_FALSE(ball.visible);
    CHECK_FALSE(ball.material.color.has_value());  // unset values stay unset
    CHECK_FALSE(ball.spin.has_value());

    const auto& tri = scene.objects[2];
    CHECK(tri.name == "object2");  // unnamed objects are named by index
    CHECK_FALSE(tri.primitive.has_value());
    CHECK(std::filesystem::equivalent(tri.mesh, dir.file("models/tri.obj")));
    // mesh_at points at the mesh path's value.
    CHECK(tri.mesh_at.line == 59);
    CHECK(tri.mesh_at.column == 11);
    REQUIRE(tri.spin.has_value());
    CHECK(tri.spin->axis == glm::vec3(0, 0, 2));
    CHECK(tri.spin->turns == 1);
}

TEST_CASE("colours: lists are linear and hex strings are sRGB converted to linear", "[scene]") {
    TempDir dir("scene");
    SECTION("dark grey uses the linear segment of the sRGB curve") {
        std::string path =
            write_text(dir.file("s.yaml"),
                       std::string("output:\n  background: '#0a0a0a80'\n") + kMinimalObjects);
        auto bg = load(path).output.background;
        float expected = 10.0f / 255.0f / 12.92f;  // 0.0030353
        CHECK(close_to(bg.r, expected, 1e-7f));
        CHECK(close_to(bg.g, expected, 1e-7f));
        CHECK(close_to(bg.b, expected, 1e-7f));
        CHECK(close_to(bg.a, 128.0f / 255.0f));  // alpha is not converted
    }
    SECTION("every channel byte converts by the sRGB formula") {
        std::string path =
            write_text(dir.file("s.yaml"),
                       std::string("output:\n  background: '#3366cc'\n") + kMinimalObjects);
        auto bg = load(path).output.background;
        CHECK(close_to(bg.r, srgb_byte_to_linear(0x33)));
        CHECK(close_to(bg.g, srgb_byte_to_linear(0x66)));
        CHECK(close_to(bg.b, srgb_byte_to_linear(0xcc)));
        CHECK(close_to(bg.a, 1));
    }
    SECTION("mid grey") {
        std::string path =
            write_text(dir.file("s.yaml"),
                       std::string("output:\n  background: '#808080'\n") + kMinimalObjects);
        CHECK(close_to(load(path).output.background.r, 0.2158605f));
    }
    SECTION("a list is taken as linear, with optional alpha") {
        std::string path = write_text(
            dir.file("s.yaml"),
            std::string("output:\n  background: [0.5, 0.25, 0.125, 0.5]\n") + kMinimalObjects);
        CHECK(load(path).output.background == glm::vec4(0.5f, 0.25f, 0.125f, 0.5f));
        path = write_text(
            dir.file("s.yaml"),
            std::string("output:\n  background: [0.5, 0.25, 0.125]\n") + kMinimalObjects);
        CHECK(load(path).output.background == glm::vec4(0.5f, 0.25f, 0.125f, 1.0f));
    }
    SECTION("material colours accept hex too") {
        std::string path =
            write_text(dir.file("s.yaml"),
                       "objects:\n  - primitive: cube\n    material:\n      color: '#ff0000'\n");
        auto color = load(path).objects[0].material.color;
        REQUIRE(color.has_value());
        CHECK(*color == glm::vec3(1, 0, 0));
    }
}

TEST_CASE("passes and formats accept a single word or a list", "[scene]") {
    TempDir dir("scene");
    std::string path = write_text(
        dir.file("s.yaml"),
        std::string("output:\n  passes: depth\n  formats: [png, exr]\n") + kMinimalObjects);
    auto out = load(path).output;
    CHECK_FALSE(out.write_color);
    CHECK(out.write_depth);
    CHECK(out.write_png);
    CHECK(out.write_exr);
}

TEST_CASE("style presets are found by name, by path and beside the scene", "[scene][style]") {
    TempDir dir("scene");
    SECTION("a preset from the styles folder by name") {
        std::string path =
            write_text(dir.file("s.yaml"), std::string("style: flat\n") + kMinimalObjects);
        auto style = load(path).style;
        CHECK(style.name == "flat");
        CHECK(style.shading == facet::ShadingModel::flat);
        CHECK_FALSE(style.description.empty());
        path = write_text(dir.file("s.yaml"), std::string("style: normals\n") + kMinimalObjects);
        CHECK(load(path).style.shading == facet::ShadingModel::normal);
        path =
            write_text(dir.file("s.yaml"), std::string("style: blinn-phong\n") + kMinimalObjects);
        CHECK(load(path).style.shading == facet::ShadingModel::blinn_phong);
    }
    SECTION("a styles/ folder beside the scene is searched after the given folders") {
        write_text(dir.file("styles/mine.yaml"), "description: my own\nshading: unlit\n");
        std::string path =
            write_text(dir.file("s.yaml"), std::string("style: mine\n") + kMinimalObjects);
        auto style = load(path).style;
        CHECK(style.name == "mine");
        CHECK(style.shading == facet::ShadingModel::unlit);
        CHECK(style.description == "my own");
    }
    SECTION("the first folder holding a name wins") {
        write_text(dir.file("first/look.yaml"), "shading: depth\n");
        write_text(dir.file("second/look.yaml"), "shading: gouraud\n");
        SceneOptions options;
        options.style_dirs = {dir.file("first"), dir.file("second")};
        std::string path =
            write_text(dir.file("s.yaml"), std::string("style: look\n") + kMinimalObjects);
        CHECK(load(path, options).style.shading == facet::ShadingModel::depth);
        options.style_dirs = {dir.file("second"), dir.file("first")};
        CHECK(load(path, options).style.shading == facet::ShadingModel::gouraud);
    }
    SECTION("a style file path relative to the scene") {
        write_text(dir.file("looks/custom.yaml"), "name: custom look\nshading: gouraud\n");
        std::string path =
            write_text(dir.file("scenes/s.yaml"),
                       std::string("style: ../looks/custom.yaml\n") + kMinimalObjects);
        auto style = load(path).style;
        CHECK(style.name == "custom look");
        CHECK(style.shading == facet::ShadingModel::gouraud);
    }
}

TEST_CASE("an unknown style preset name lists the available presets", "[scene][style]") {
    TempDir dir("scene");
    const std::string text = std::string("style: toonish\n") + kMinimalObjects;
    std::string path = write_text(dir.file("s.yaml"), text);
    std::string message = load_error(path);
    check_error_at(message, path, line_col(text, "toonish"), "style");
    CHECK_THAT(message, Contains("toonish"));
    CHECK_THAT(message, Contains("available"));
    // Every preset file in the styles folder is named.
    int presets = 0;
    for (const auto& entry : std::filesystem::directory_iterator(FACET_STYLES_DIR)) {
        if (entry.path().extension() != ".yaml") continue;
        ++presets;
        CHECK_THAT(message, Contains(entry.path().stem().string()));
    }
    CHECK(presets > 0);
}

TEST_CASE("errors inside a style file name that file", "[scene][style]") {
    TempDir dir("scene");
    const std::string style_text = "description: broken\nshading: toon\n";
    std::string style_path = write_text(dir.file("looks/bad.yaml"), style_text);
    std::string path =
        write_text(dir.file("s.yaml"), std::string("style: looks/bad.yaml\n") + kMinimalObjects);
    std::string message = load_error(path);
    check_error_at(message, style_path, line_col(style_text, "toon\n"), "shading");
    CHECK_THAT(message, Contains("toon"));
}

// ---------------------------------------------------------------------------
// Invalid scenes: each case names the key and where its text is.

namespace {

struct ErrorCase {
    const char* name;
    std::string text;
    std::string key;     // dotted key the message must quote ("" for none)
    std::string needle;  // text at the reported position...
    size_t offset;       // ...plus this many characters
    std::string says;    // part of the message
};

void run_error_cases(const std::vector<ErrorCase>& cases) {
    for (const auto& c : cases) {
        DYNAMIC_SECTION(c.name) {
            TempDir dir("scene-error");
            write_text(dir.file("model.stl"), "solid x\nendsolid x\n");
            std::string path = write_text(dir.file("bad.yaml"), c.text);
            std::string message = load_error(path);
            check_error_at(message, path, line_col(c.text, c.needle, c.offset), c.key);
            CHECK_THAT(message, Contains(c.says));
        }
    }
}

}  // namespace

TEST_CASE("unknown keys are rejected at every level", "[scene][errors]") {
    std::string objects = kMinimalObjects;
    run_error_cases({
        {"root", objects + "outptu:\n  size: [1, 1]\n", "outptu", "outptu", 0, "unknown key"},
        {"output", "output:\n  sizes: [1, 2]\n" + objects, "output.sizes", "sizes", 0,
         "unknown key"},
        {"camera", "camera:\n  fov: 30\n  fovy: 30\n" + objects, "camera.fovy", "fovy", 0,
         "unknown key"},
        {"orbit", "camera:\n  orbit:\n    radious: 3\n" + objects, "camera.orbit.radious",
         "radious", 0, "unknown key"},
        {"light",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n    colour: [1, 1, 1]\n" + objects,
         "lights.0.colour", "colour", 0, "unknown key"},
        {"object", "objects:\n  - primitive: cube\n    translation: [0, 0, 0]\n",
         "objects.0.translation", "translation", 0, "unknown key"},
        {"material",
         "objects:\n  - primitive: cube\n  - primitive: sphere\n    material:\n      colour: [1, "
         "0, 0]\n",
         "objects.1.material.colour", "colour", 0, "unknown key"},
        {"primitive", "objects:\n  - primitive:\n      type: cone\n      radius2: 1\n",
         "objects.0.primitive.radius2", "radius2", 0, "unknown key"},
        {"spin", "objects:\n  - primitive: cube\n    spin:\n      speed: 2\n",
         "objects.0.spin.speed", "speed", 0, "unknown key"},
        {"inline style", "style:\n  shadin: flat\n" + objects, "style.shadin", "shadin", 0,
         "unknown key"},
    });
}

TEST_CASE("the unknown-key message lists the allowed keys", "[scene][errors]") {
    TempDir dir("scene");
    std::string path =
        write_text(dir.file("s.yaml"), std::string("camera:\n  zoom: 2\n") + kMinimalObjects);
    std::string message = load_error(path);
    for (const char* key : {"position", "target", "up", "fov", "near", "far", "orbit"})
        CHECK_THAT(message, Contains(key));
}

TEST_CASE("values of the wrong type are rejected", "[scene][errors]") {
    std::string objects = kMinimalObjects;
    run_error_cases({
        {"size not a list", "output:\n  size: 64\n" + objects, "output.size", "64", 0,
         "[width, height]"},
        {"size of three", "output:\n  size: [64, 48, 2]\n" + objects, "output.size", "[64", 0,
         "[width, height]"},
        {"size not whole", "output:\n  size: [64.5, 48]\n" + objects, "output.size.0", "64.5", 0,
         "whole number"},
        {"fov a word", "camera:\n  fov: wide\n" + objects, "camera.fov", "wide", 0,
         "must be a number"},
        {"camera a number", "camera: 5\n" + objects, "camera", "5", 0, "mapping"},
        {"lights not a list", "lights: directional\n" + objects, "lights", "directional", 0,
         "must be a list"},
        {"objects a mapping", "objects:\n  primitive: cube\n", "objects", "primitive", 0,
         "must be a list"},
        {"translate of two", "objects:\n  - primitive: cube\n    translate: [1, 2]\n",
         "objects.0.translate", "[1, 2]", 0, "3 numbers"},
        {"translate item a word", "objects:\n  - primitive: cube\n    translate: [1, x, 3]\n",
         "objects.0.translate.1", "x, 3", 0, "must be a number"},
        {"colour a word", "objects:\n  - primitive: cube\n    material:\n      color: red\n",
         "objects.0.material.color", "red", 0, "colour"},
        {"colour with alpha where RGB is wanted",
         "objects:\n  - primitive: cube\n    material:\n      color: '#ff000080'\n",
         "objects.0.material.color", "'#ff", 0, "RGB"},
        {"visible not a boolean", "objects:\n  - primitive: cube\n    visible: maybe\n",
         "objects.0.visible", "maybe", 0, "true or false"},
        {"unknown pass", "output:\n  passes: [color, normals]\n" + objects, "output.passes.1",
         "normals", 0, "must be one of"},
        {"unknown format", "output:\n  formats: tiff\n" + objects, "output.formats", "tiff", 0,
         "png, exr"},
        {"unknown primitive", "objects:\n  - primitive: teapot\n", "objects.0.primitive", "teapot",
         0, "cube"},
        {"unknown light type", "lights:\n  - type: spot\n    direction: [0, -1, 0]\n" + objects,
         "lights.0.type", "spot", 0, "directional, point"},
        {"unknown wrap", "objects:\n  - primitive: cube\n    material:\n      wrap: mirror\n",
         "objects.0.material.wrap", "mirror", 0, "repeat, clamp"},
        {"spin axis a word", "objects:\n  - primitive: cube\n    spin:\n      axis: w\n",
         "objects.0.spin.axis", "w\n", 0, "x, y, z"},
        {"object name a list", "objects:\n  - primitive: cube\n    name: [a, b]\n",
         "objects.0.name", "[a, b]", 0, "text"},
        {"frames a list", "output:\n  frames: [1, 2]\n" + objects, "output.frames", "[1, 2]", 0,
         "text"},
        {"shading unknown", "style:\n  shading: toon\n" + objects, "style.shading", "toon", 0,
         "phong"},
        {"scale a word", "objects:\n  - primitive: cube\n    scale: big\n", "objects.0.scale",
         "big", 0, "number"},
    });
}

TEST_CASE("numbers out of range are rejected with the allowed range", "[scene][errors]") {
    std::string objects = kMinimalObjects;
    run_error_cases({
        {"fov too wide", "camera:\n  fov: 500\n" + objects, "camera.fov", "500", 0,
         "between 1 and 179"},
        {"fov zero", "camera:\n  fov: 0\n" + objects, "camera.fov", "0\n", 0, "between 1 and 179"},
        {"negative shininess",
         "objects:\n  - primitive: cube\n  - primitive: sphere\n    material:\n      shininess: "
         "-3\n",
         "objects.1.material.shininess", "-3", 0, "between 0 and"},
        {"zero width", "output:\n  size: [0, 48]\n" + objects, "output.size.0", "0, 48", 0,
         "between 1 and"},
        {"huge height", "output:\n  size: [64, 100000]\n" + objects, "output.size.1", "100000", 0,
         "between 1 and"},
        {"png compression", "output:\n  png_compression: 10\n" + objects, "output.png_compression",
         "10", 0, "between 0 and 9"},
        {"fps zero", "output:\n  fps: 0\n" + objects, "output.fps", "0\n", 0, "between"},
        {"orbit elevation", "camera:\n  orbit:\n    elevation: 90\n" + objects,
         "camera.orbit.elevation", "90", 0, "between"},
        {"orbit radius", "camera:\n  orbit:\n    radius: -1\n" + objects, "camera.orbit.radius",
         "-1", 0, "between"},
        {"light intensity",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n    intensity: -1\n" + objects,
         "lights.0.intensity", "-1", 0, "between"},
        {"segments", "objects:\n  - primitive:\n      type: cylinder\n      segments: 2\n",
         "objects.0.primitive.segments", "2\n", 0, "between 3 and"},
        {"negative colour",
         "objects:\n  - primitive: cube\n    material:\n      color: [1, -0.5, 0]\n",
         "objects.0.material.color.1", "-0.5", 0, ">= 0"},
        {"scale zero", "objects:\n  - primitive: cube\n    scale: 0\n", "objects.0.scale", "0\n", 0,
         "zero"},
        {"scale zero on one axis", "objects:\n  - primitive: cube\n    scale: [1, 0, 1]\n",
         "objects.0.scale", "[1, 0", 0, "zero"},
        {"depth range reversed", "output:\n  depth_range: [5, 1]\n" + objects, "output.depth_range",
         "[5, 1]", 0, "near"},
        {"not finite", "camera:\n  fov: .nan\n" + objects, "camera.fov", ".nan", 0, "number"},
        {"spin axis zero", "objects:\n  - primitive: cube\n    spin:\n      axis: [0, 0, 0]\n",
         "objects.0.spin.axis", "[0, 0, 0]", 0, "[0, 0, 0]"},
        {"up zero", "camera:\n  up: [0, 0, 0]\n" + objects, "camera.up", "[0, 0, 0]", 0,
         "[0, 0, 0]"},
    });
}

TEST_CASE("missing required keys are reported at the mapping that lacks them", "[scene][errors]") {
    std::string objects = kMinimalObjects;
    run_error_cases({
        {"no objects", "camera:\n  fov: 30\n", "", "camera", 0, "missing required key 'objects'"},
        {"empty objects", "objects: []\n", "objects", "[]", 0, "no objects"},
        {"light without type", "lights:\n  - direction: [0, -1, 0]\n" + objects, "lights.0",
         "direction", 0, "missing required key 'type'"},
        {"directional without direction",
         "lights:\n  - type: directional\n    intensity: 2\n" + objects, "lights.0", "type", 0,
         "missing required key 'direction'"},
        {"point without position", objects + "lights:\n  - type: point\n", "lights.0", "type", 0,
         "missing required key 'position'"},
        {"directional with a position",
         "lights:\n  - type: directional\n    direction: [0, -1, 0]\n    position: [1, 2, 3]\n" +
             objects,
         "lights.0.position", "[1, 2, 3]", 0, "direction"},
        {"point with a direction",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n    direction: [0, -1, 0]\n" + objects,
         "lights.0.direction", "[0, -1, 0]", 0, "position"},
        {"object with neither mesh nor primitive",
         "objects:\n  - primitive: cube\n  - name: nothing\n", "objects.1", "name: nothing", 0,
         "exactly one"},
        {"object with both", "objects:\n  - mesh: model.stl\n    primitive: cube\n", "objects.0",
         "mesh", 0, "exactly one"},
        {"primitive mapping without type", "objects:\n  - primitive:\n      size: 2\n",
         "objects.0.primitive", "size", 0, "missing required key 'type'"},
    });
}

TEST_CASE("the camera's far plane must be beyond its near plane", "[scene][errors]") {
    std::string objects = kMinimalObjects;
    run_error_cases({
        {"far below near", "camera:\n  near: 10\n  far: 5\n" + objects, "camera.far", "5\n", 0,
         "greater than near"},
        {"far equal to near", "camera:\n  near: 2\n  far: 2\n" + objects, "camera.far", "far: 2", 5,
         "greater than near"},
        // Without `far` the default (100) applies and the camera mapping is blamed.
        {"near beyond the default far", "camera:\n  near: 200\n" + objects, "camera", "near", 0,
         "near"},
        {"position equals target",
         "camera:\n  position: [1, 1, 1]\n  target: [1, 1, 1]\n" + objects, "camera", "position", 0,
         "same point"},
    });
}

TEST_CASE("mesh and texture files must exist and have a supported format", "[scene][errors]") {
    run_error_cases({
        {"missing mesh", "objects:\n  - mesh: models/missing.obj\n", "objects.0.mesh", "models/", 0,
         "missing.obj"},
        {"unsupported extension", "objects:\n  - name: stl\n    mesh: model.stl\n",
         "objects.0.mesh", "model.stl", 0, "unsupported mesh format '.stl'"},
        {"missing texture",
         "objects:\n  - primitive: cube\n    material:\n      texture: wood.png\n",
         "objects.0.material.texture", "wood.png", 0, "not found"},
    });
}

TEST_CASE("mesh extensions are matched without regard to case", "[scene]") {
    TempDir dir("scene");
    write_text(dir.file("M.OBJ"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write_text(dir.file("m.glb"), "x");
    std::string path =
        write_text(dir.file("s.yaml"), "objects:\n  - mesh: M.OBJ\n  - mesh: m.glb\n");
    auto scene = load(path);
    REQUIRE(scene.objects.size() == 2);
    CHECK(std::filesystem::equivalent(scene.objects[0].mesh, dir.file("M.OBJ")));
}

TEST_CASE("object names must be unique", "[scene][errors]") {
    run_error_cases({
        {"two named alike",
         "objects:\n  - name: box\n    primitive: cube\n  - name: box\n    primitive: sphere\n",
         "objects.1.name", "box\n    primitive: sphere", 0, "already named 'box'"},
        // The second object is named "object1" by its index, like the first's
        // explicit name; the error points at the unnamed object.
        {"clash with an automatic name",
         "objects:\n  - name: object1\n    primitive: cube\n  - primitive: sphere\n", "objects.1",
         "primitive: sphere", 0, "already named 'object1'"},
    });
}

TEST_CASE("a key given twice in one mapping is an error", "[scene][errors]") {
    // YAML requires unique keys; silently taking one of the two would hide typos.
    std::string objects = kMinimalObjects;
    run_error_cases({
        {"camera.fov twice", "camera:\n  fov: 30\n  fov: 40\n" + objects, "camera.fov", "fov: 40",
         0, "more than once"},
        {"objects twice", objects + "objects:\n  - primitive: sphere\n", "objects",
         "objects:\n  - primitive: sphere", 0, "more than once"},
    });
}

TEST_CASE("bad frame ranges in the scene name output.frames", "[scene][errors]") {
    std::string objects = kMinimalObjects;
    run_error_cases({
        {"reversed", "output:\n  frames: 5-1\n" + objects, "output.frames", "5-1", 0, "before"},
        {"empty item", "output:\n  frames: \"1,,2\"\n" + objects, "output.frames", "\"1,,2\"", 0,
         "empty item"},
        {"zero step", "output:\n  frames: 1-10:0\n" + objects, "output.frames", "1-10:0", 0,
         "step"},
        {"not a number", "output:\n  frames: first\n" + objects, "output.frames", "first", 0,
         "whole number"},
        {"too many", "output:\n  frames: 1-2000000\n" + objects, "output.frames", "1-2000000", 0,
         "1000000"},
    });
}

TEST_CASE("YAML syntax errors give the line and column of the fault", "[scene][errors]") {
    run_error_cases({
        // A tab may not indent YAML; the tab is at the start of line 3.
        {"tab indentation", "objects:\n  - primitive: cube\n\tname: a\n", "", "\tname", 0,
         "YAML syntax error"},
        // "near" is indented deeper than "fov", so its ':' cannot start a value.
        {"deeper indentation", "camera:\n  fov: 30\n   near: 1\n" + std::string(kMinimalObjects),
         "", "near: 1", 4, "YAML syntax error"},
        // "bad" is indented less than the list it follows but more than the root.
        {"shallower indentation", "objects:\n  - primitive: cube\n bad: 1\n", "", "bad", 0,
         "YAML syntax error"},
    });
}

TEST_CASE("files that are not scenes at all", "[scene][errors]") {
    TempDir dir("scene");
    SECTION("empty file") {
        std::string path = write_text(dir.file("empty.yaml"), "");
        std::string message = load_error(path);
        CHECK_THAT(message, Contains(path) && Contains("empty"));
    }
    SECTION("a list instead of a mapping") {
        std::string path = write_text(dir.file("list.yaml"), "- primitive: cube\n");
        std::string message = load_error(path);
        check_error_at(message, path, "1:1", "");
        CHECK_THAT(message, Contains("mapping"));
    }
    SECTION("missing file") {
        std::string path = dir.file("nothing-here.yaml");
        std::string message = load_error(path);
        CHECK_THAT(message, Contains(path));
    }
}

TEST_CASE("hand-counted positions agree with the reported ones", "[scene][errors]") {
    // The same checks as above with the positions counted by hand, so that a
    // mistake shared by line_col() and the parser cannot hide.
    TempDir dir("scene");
    std::string path = write_text(dir.file("hand.yaml"),
                                  "objects:\n"               // line 1
                                  "  - name: a\n"            // line 2
                                  "    primitive: cube\n"    // line 3
                                  "  - name: b\n"            // line 4
                                  "    primitive: sphere\n"  // line 5
                                  "    material:\n"          // line 6
                                  "      shininess: -3\n");  // line 7, '-' in column 18
    std::string message = load_error(path);
    CHECK_THAT(message, Contains(path + ":7:18: 'objects.1.material.shininess'"));

    path = write_text(dir.file("hand2.yaml"),
                      "camera:\n  fov: 30\n  fovy: 30\nobjects:\n  - primitive: cube\n");
    CHECK_THAT(load_error(path), Contains(path + ":3:3: 'camera.fovy'"));
}

// ---------------------------------------------------------------------------
// Overrides (-D key.path=value)

namespace {

SceneOptions with_overrides(std::vector<Override> overrides) {
    SceneOptions options = with_styles();
    options.overrides = std::move(overrides);
    return options;
}

Override define(const std::string& path, const std::string& value) {
    return {path, value, "command line -D " + path + "=" + value};
}

const char* kOverrideScene = R"(camera:
  fov: 45
  position: [0, 1, 5]
objects:
  - name: box
    primitive: cube
    material:
      color: [0, 0, 1]
  - name: ball
    primitive: sphere
)";

}  // namespace

TEST_CASE("overrides replace values from the scene file", "[scene][override]") {
    TempDir dir("override");
    std::string path = write_text(dir.file("s.yaml"), kOverrideScene);
    REQUIRE(load(path).camera.fov == 45);

    SECTION("a number") {
        CHECK(load(path, with_overrides({define("camera.fov", "30")})).camera.fov == 30);
    }
    SECTION("a list item's nested value, given as a YAML list") {
        auto scene = load(path, with_overrides({define("objects.0.material.color", "[1,0,0]")}));
        REQUIRE(scene.objects[0].material.color.has_value());
        CHECK(*scene.objects[0].material.color == glm::vec3(1, 0, 0));
        CHECK_FALSE(scene.objects[1].material.color.has_value());
    }
    SECTION("a nested key that did not exist is created") {
        auto scene = load(path, with_overrides({define("objects.1.material.color", "[0,1,0]"),
                                                define("camera.orbit.radius", "7")}));
        REQUIRE(scene.objects[1].material.color.has_value());
        CHECK(*scene.objects[1].material.color == glm::vec3(0, 1, 0));
        REQUIRE(scene.camera.orbit.has_value());
        CHECK(scene.camera.orbit->radius == 7);
        CHECK(scene.camera.orbit->elevation == 20);  // the rest keeps its defaults
        CHECK(scene.camera.fov == 45);               // siblings are untouched
    }
    SECTION("a whole section that the file does not have") {
        auto scene = load(path, with_overrides({define("output.size", "[40, 30]")}));
        CHECK(scene.output.width == 40);
        CHECK(scene.output.height == 30);
    }
    SECTION("a whole list item") {
        auto scene =
            load(path, with_overrides({define("objects.1", "{name: cone, primitive: cone}")}));
        CHECK(scene.objects[1].name == "cone");
        REQUIRE(scene.objects[1].primitive.has_value());
        CHECK(scene.objects[1].primitive->type == "cone");
        CHECK(scene.objects[0].name == "box");
    }
    SECTION("later overrides win over earlier ones") {
        auto scene =
            load(path, with_overrides({define("camera.fov", "30"), define("camera.fov", "60")}));
        CHECK(scene.camera.fov == 60);
    }
    SECTION("a style preset by name") {
        auto scene = load(path, with_overrides({define("style", "gouraud")}));
        CHECK(scene.style.name == "gouraud");
        CHECK(scene.style.shading == facet::ShadingModel::gouraud);
    }
    SECTION("a '#rrggbb' colour, which YAML alone would read as a comment") {
        auto scene = load(path, with_overrides({define("output.background", "#ff0000")}));
        CHECK(close_to(scene.output.background.r, 1));
        CHECK(close_to(scene.output.background.g, 0));
        CHECK(close_to(scene.output.background.b, 0));
        scene = load(path, with_overrides({define("objects.0.material.color", "#808080")}));
        REQUIRE(scene.objects[0].material.color.has_value());
        CHECK(close_to(scene.objects[0].material.color->g, 0.2158605f));
    }
}

TEST_CASE("an invalid overridden value names the command line, not the file", "[scene][override]") {
    TempDir dir("override");
    std::string path = write_text(dir.file("s.yaml"), kOverrideScene);

    SECTION("out of range") {
        std::string message = load_error(path, with_overrides({define("camera.fov", "500")}));
        CHECK_THAT(message, Contains("command line -D camera.fov=500"));
        CHECK_THAT(message, Contains("'camera.fov'"));
        CHECK_THAT(message, Contains("between 1 and 179"));
        CHECK_THAT(message, !Contains(path));  // the file's fov was fine
    }
    SECTION("inside an overridden list") {
        std::string message =
            load_error(path, with_overrides({define("objects.0.material.color", "[1,-1,0]")}));
        CHECK_THAT(message, Contains("command line -D objects.0.material.color=[1,-1,0]"));
        CHECK_THAT(message, Contains("'objects.0.material.color.1'"));
    }
    SECTION("an unknown key brought in by an override") {
        std::string message = load_error(path, with_overrides({define("camera.fovy", "30")}));
        CHECK_THAT(message, Contains("command line -D camera.fovy=30"));
        CHECK_THAT(message, Contains("unknown key"));
    }
    SECTION("a value that is not YAML") {
        std::string message =
            load_error(path, with_overrides({define("camera.position", "[1, 2")}));
        CHECK_THAT(message, Contains("command line -D camera.position=[1, 2"));
    }
    SECTION("errors in the file are still reported at the file, next to overrides") {
        std::string text = std::string(kOverrideScene) + "    scale: 0\n";
        write_text(path, text);
        std::string message = load_error(path, with_overrides({define("camera.fov", "30")}));
        check_error_at(message, path, line_col(text, "scale: 0", 7), "objects.1.scale");
    }
}

TEST_CASE("override paths must exist where they go through lists", "[scene][override]") {
    TempDir dir("override");
    std::string path = write_text(dir.file("s.yaml"), kOverrideScene);

    SECTION("index past the end") {
        std::string message = load_error(path, with_overrides({define("objects.2.name", "x")}));
        CHECK_THAT(message, Contains("command line -D objects.2.name=x"));
        CHECK_THAT(message, Contains("'objects.2'"));
        CHECK_THAT(message, Contains("0 to 1"));
    }
    SECTION("negative index") {
        std::string message = load_error(path, with_overrides({define("objects.-1.name", "x")}));
        CHECK_THAT(message, Contains("'objects.-1'"));
    }
    SECTION("index that is not a number") {
        std::string message = load_error(path, with_overrides({define("objects.first.name", "x")}));
        CHECK_THAT(message, Contains("'objects.first'"));
    }
    SECTION("an empty list") {
        write_text(path, "lights: []\nobjects:\n  - primitive: cube\n");
        std::string message = load_error(path, with_overrides({define("lights.0.type", "point")}));
        CHECK_THAT(message, Contains("'lights.0'"));
        CHECK_THAT(message, Contains("empty"));
    }
    SECTION("an empty path or path part") {
        std::string message = load_error(path, with_overrides({define("", "1")}));
        CHECK_THAT(message, Contains("empty"));
        message = load_error(path, with_overrides({define("camera..fov", "1")}));
        CHECK_THAT(message, Contains("empty part"));
    }
}
