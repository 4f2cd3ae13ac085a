// facet::load_scene on valid scene files: every value lands in the right
// record, defaults fill the rest, colours convert from sRGB where the format
// says so, and style presets are found where the documentation says.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using facet::Pass;
using facet::SceneDesc;
using facet::SceneOptions;
using namespace facet::test;

namespace {

// sRGB -> linear, the standard IEC 61966-2-1 formula, written out here so the
// test does not borrow the parser's.
float srgb_byte_to_linear(int byte) {
    double c = byte / 255.0;
    return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

}  // namespace

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
    CHECK(scene.output.writes(Pass::color));
    CHECK_FALSE(scene.output.writes(Pass::depth));
    CHECK(scene.output.write_png);
    CHECK_FALSE(scene.output.write_exr);
    CHECK(scene.style.name == "default");
    CHECK(scene.cameras[0].fov.value == 45);
    CHECK_FALSE(scene.cameras[0].orbit.has_value());
    REQUIRE(scene.lights.size() == 1);  // the default key light
    CHECK(scene.lights[0].camera_relative);
    CHECK(scene.lights[0].type == facet::LightType::directional);
    // A style that turns shadows on (lit-shadows, pbr) gives it a map of
    // the sun's size, not of none.
    CHECK(scene.lights[0].shadow_resolution == 2048);
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].name == "object0");
    REQUIRE(scene.objects[0].primitive.has_value());
    CHECK(scene.objects[0].primitive->spec.type == "cube");
    CHECK(scene.objects[0].mesh.empty());
    CHECK(scene.objects[0].scale.value == glm::vec3(1));
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
    CHECK(out.writes(Pass::color));
    CHECK(out.writes(Pass::depth));
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

    const auto& cam = scene.cameras[0];
    CHECK(cam.position.value == glm::vec3(1, 2, 3));
    CHECK(cam.target.value == glm::vec3(0, 0.5f, 0));
    CHECK(cam.up.value == glm::vec3(0, 0, 1));
    CHECK(cam.fov.value == 60);
    CHECK(cam.near->value == 0.5f);
    CHECK(cam.far->value == 50);
    REQUIRE(cam.orbit.has_value());
    CHECK(cam.orbit->center.value == glm::vec3(1, 0, -1));
    CHECK(cam.orbit->radius.value == 7.5f);
    CHECK(cam.orbit->elevation.value == 30);
    CHECK(cam.orbit->start_angle.value == 90);
    CHECK(cam.orbit->turns == -2);

    REQUIRE(scene.lights.size() == 2);
    CHECK(scene.lights[0].type == facet::LightType::directional);
    CHECK(scene.lights[0].direction.value == glm::vec3(0, -1, -1));
    CHECK(scene.lights[0].color.value == glm::vec3(1, 0.5f, 0.25f));
    CHECK(scene.lights[0].intensity.value == 2);
    CHECK(scene.lights[1].type == facet::LightType::point);
    CHECK(scene.lights[1].position.value == glm::vec3(3, 4, 5));
    CHECK(scene.lights[1].intensity.value == 1);
    CHECK(scene.lights[1].color.value == glm::vec3(1, 1, 1));

    REQUIRE(scene.objects.size() == 3);
    const auto& box = scene.objects[0];
    CHECK(box.name == "box");
    REQUIRE(box.primitive.has_value());
    CHECK(box.primitive->spec.type == "cube");
    CHECK(box.translate.value == glm::vec3(1, 2, 3));
    CHECK(box.rotate.value == glm::vec3(10, 20, 30));
    CHECK(box.scale.value == glm::vec3(2, 2, 2));  // a number scales every axis
    REQUIRE(box.material.color.has_value());
    CHECK(box.material.color->value == glm::vec3(0.8f, 0.1f, 0.1f));
    CHECK(box.material.ambient->value == 0.2f);
    CHECK(box.material.diffuse->value == 0.7f);
    CHECK(box.material.specular->value == 0.5f);
    CHECK(box.material.shininess->value == 64.0f);
    REQUIRE(box.material.texture.has_value());
    CHECK(std::filesystem::equivalent(box.material.texture->path, dir.file("textures/wood.png")));
    CHECK(box.material.wrap == facet::Wrap::clamp);
    CHECK(box.material.double_sided == true);
    REQUIRE(box.spin.has_value());
    CHECK(box.spin->axis == glm::vec3(1, 0, 0));
    CHECK(box.spin->turns == 3);

    const auto& ball = scene.objects[1];
    CHECK(ball.name == "ball");
    REQUIRE(ball.primitive.has_value());
    CHECK(ball.primitive->spec.type == "sphere");
    CHECK(ball.primitive->spec.radius == 0.75f);
    CHECK(ball.primitive->spec.segments == 24);
    CHECK(ball.primitive->spec.rings == 12);
    CHECK(ball.scale.value == glm::vec3(1, 2, 3));  // a list scales per axis
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
        std::string path = write_text(dir.file("s.yaml"),
                                      "output:\n  background: '#0a0a0a80'\n" + kMinimalObjects);
        auto bg = load(path).output.background;
        float expected = 10.0f / 255.0f / 12.92f;  // 0.0030353
        CHECK(close_to(bg.r, expected, 1e-7f));
        CHECK(close_to(bg.g, expected, 1e-7f));
        CHECK(close_to(bg.b, expected, 1e-7f));
        CHECK(close_to(bg.a, 128.0f / 255.0f));  // alpha is not converted
    }
    SECTION("every channel byte converts by the sRGB formula") {
        std::string path =
            write_text(dir.file("s.yaml"), "output:\n  background: '#3366cc'\n" + kMinimalObjects);
        auto bg = load(path).output.background;
        CHECK(close_to(bg.r, srgb_byte_to_linear(0x33)));
        CHECK(close_to(bg.g, srgb_byte_to_linear(0x66)));
        CHECK(close_to(bg.b, srgb_byte_to_linear(0xcc)));
        CHECK(close_to(bg.a, 1));
    }
    SECTION("mid grey") {
        std::string path =
            write_text(dir.file("s.yaml"), "output:\n  background: '#808080'\n" + kMinimalObjects);
        CHECK(close_to(load(path).output.background.r, 0.2158605f));
    }
    SECTION("a list is taken as linear, with optional alpha") {
        std::string path =
            write_text(dir.file("s.yaml"),
                       "output:\n  background: [0.5, 0.25, 0.125, 0.5]\n" + kMinimalObjects);
        CHECK(load(path).output.background == glm::vec4(0.5f, 0.25f, 0.125f, 0.5f));
        path = write_text(dir.file("s.yaml"),
                          "output:\n  background: [0.5, 0.25, 0.125]\n" + kMinimalObjects);
        CHECK(load(path).output.background == glm::vec4(0.5f, 0.25f, 0.125f, 1.0f));
    }
    SECTION("material colours accept hex too") {
        std::string path =
            write_text(dir.file("s.yaml"),
                       "objects:\n  - primitive: cube\n    material:\n      color: '#ff0000'\n");
        auto color = load(path).objects[0].material.color;
        REQUIRE(color.has_value());
        CHECK(color->value == glm::vec3(1, 0, 0));
    }
}

TEST_CASE("passes and formats accept a single word or a list", "[scene]") {
    TempDir dir("scene");
    std::string path = write_text(
        dir.file("s.yaml"), "output:\n  passes: depth\n  formats: [png, exr]\n" + kMinimalObjects);
    auto out = load(path).output;
    CHECK_FALSE(out.writes(Pass::color));
    CHECK(out.writes(Pass::depth));
    CHECK(out.write_png);
    CHECK(out.write_exr);
}

TEST_CASE("style presets are found by name, by path and beside the scene", "[scene][style]") {
    TempDir dir("scene");
    SECTION("a preset from the styles folder by name") {
        std::string path = write_text(dir.file("s.yaml"), "style: flat\n" + kMinimalObjects);
        auto style = load(path).style;
        CHECK(style.name == "flat");
        CHECK(style.shading == facet::ShadingModel::flat);
        CHECK_FALSE(style.description.empty());
        path = write_text(dir.file("s.yaml"), "style: normals\n" + kMinimalObjects);
        CHECK(load(path).style.shading == facet::ShadingModel::normal);
        path = write_text(dir.file("s.yaml"), "style: blinn-phong\n" + kMinimalObjects);
        CHECK(load(path).style.shading == facet::ShadingModel::blinn_phong);
    }
    SECTION("a styles/ folder beside the scene is searched after the given folders") {
        write_text(dir.file("styles/mine.yaml"), "description: my own\nshading: unlit\n");
        std::string path = write_text(dir.file("s.yaml"), "style: mine\n" + kMinimalObjects);
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
        std::string path = write_text(dir.file("s.yaml"), "style: look\n" + kMinimalObjects);
        CHECK(load(path, options).style.shading == facet::ShadingModel::depth);
        options.style_dirs = {dir.file("second"), dir.file("first")};
        CHECK(load(path, options).style.shading == facet::ShadingModel::gouraud);
    }
    SECTION("a style file path relative to the scene") {
        write_text(dir.file("looks/custom.yaml"), "name: custom look\nshading: gouraud\n");
        std::string path = write_text(dir.file("scenes/s.yaml"),
                                      "style: ../looks/custom.yaml\n" + kMinimalObjects);
        auto style = load(path).style;
        CHECK(style.name == "custom look");
        CHECK(style.shading == facet::ShadingModel::gouraud);
    }
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
