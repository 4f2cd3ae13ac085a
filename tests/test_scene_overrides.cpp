// facet::load_scene with overrides (-D key.path=value): they replace or add
// values before validation, and errors in what they bring name the command
// line rather than the file.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using Catch::Contains;
using facet::Override;
using facet::SceneOptions;
using namespace facet::test;

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
    REQUIRE(load(path).cameras[0].fov.value == 45);

    SECTION("a number") {
        CHECK(load(path, with_overrides({define("camera.fov", "30")})).cameras[0].fov.value == 30);
    }
    SECTION("a list item's nested value, given as a YAML list") {
        auto scene = load(path, with_overrides({define("objects.0.material.color", "[1,0,0]")}));
        REQUIRE(scene.objects[0].material.color.has_value());
        CHECK(scene.objects[0].material.color->value == glm::vec3(1, 0, 0));
        CHECK_FALSE(scene.objects[1].material.color.has_value());
    }
    SECTION("a nested key that did not exist is created") {
        auto scene = load(path, with_overrides({define("objects.1.material.color", "[0,1,0]"),
                                                define("camera.orbit.radius", "7")}));
        REQUIRE(scene.objects[1].material.color.has_value());
        CHECK(scene.objects[1].material.color->value == glm::vec3(0, 1, 0));
        REQUIRE(scene.cameras[0].orbit.has_value());
        CHECK(scene.cameras[0].orbit->radius.value == 7);
        CHECK(scene.cameras[0].orbit->elevation.value == 20);  // the rest keeps its defaults
        CHECK(scene.cameras[0].fov.value == 45);               // siblings are untouched
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
        CHECK(scene.objects[1].primitive->spec.type == "cone");
        CHECK(scene.objects[0].name == "box");
    }
    SECTION("later overrides win over earlier ones") {
        auto scene =
            load(path, with_overrides({define("camera.fov", "30"), define("camera.fov", "60")}));
        CHECK(scene.cameras[0].fov.value == 60);
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
        CHECK(close_to(scene.objects[0].material.color->value.g, 0.2158605f));
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
