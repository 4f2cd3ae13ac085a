// Invalid light, shadow and material-alias keys: each error names the file,
// line and column, the dotted key, and the allowed range or the keys that apply.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "scene_support.hpp"
#include "support.hpp"

using Catch::Contains;
using namespace facet::test;

namespace {

struct ErrorCase {
    const char* name;
    std::string text;
    std::string key;     // dotted key the message must quote
    std::string needle;  // text at the reported position
    std::string says;    // part of the message
};

void run_error_cases(const std::vector<ErrorCase>& cases) {
    for (const auto& c : cases) {
        DYNAMIC_SECTION(c.name) {
            TempDir dir("light-error");
            std::string path = write_text(dir.file("bad.yaml"), c.text);
            std::string message = load_error(path);
            check_error_at(message, path, line_col(c.text, c.needle), c.key);
            CHECK_THAT(message, Contains(c.says));
        }
    }
}

const std::string kSpot = "lights:\n  - type: spot\n    position: [0, 3, 0]\n";

}  // namespace

TEST_CASE("light values out of range name the key and the range", "[scene][errors][lights]") {
    const std::string objects = kMinimalObjects;
    run_error_cases({
        {"outer angle too wide",
         kSpot + "    direction: [0, -1, 0]\n    outer_angle: 95\n" + objects,
         "lights.0.outer_angle", "95", "between 0.01 and 90"},
        {"inner angle negative",
         kSpot + "    direction: [0, -1, 0]\n    inner_angle: -5\n" + objects,
         "lights.0.inner_angle", "-5", "between 0 and 90"},
        {"inner wider than outer",
         kSpot + "    direction: [0, -1, 0]\n    inner_angle: 40\n    outer_angle: 30\n" + objects,
         "lights.0.inner_angle", "40", "must not be larger than outer_angle (30)"},
        {"inner wider than the default outer",
         kSpot + "    direction: [0, -1, 0]\n    inner_angle: 50\n" + objects,
         "lights.0.inner_angle", "50", "outer_angle (45)"},
        {"range zero",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n    range: 0\n" + objects,
         "lights.0.range", "0\n", "between"},
        {"kelvin too cold",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n    color: { kelvin: 500 }\n" +
             objects,
         "lights.0.color.kelvin", "500", "between 1667 and 25000"},
        {"kelvin key too hot",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n"
         "    color: { kelvin: { keys: { 1: 3000, 5: 90000 } } }\n" +
             objects,
         "lights.0.color.kelvin.keys.5", "90000", "between 1667 and 25000"},
        {"shadow resolution",
         "lights:\n  - type: directional\n    direction: [0, -1, 0]\n"
         "    shadow_resolution: 8\n" +
             objects,
         "lights.0.shadow_resolution", "8\n", "between 16 and 8192"},
        {"shadow resolution fractional",
         "lights:\n  - type: directional\n    direction: [0, -1, 0]\n"
         "    shadow_resolution: 100.5\n" +
             objects,
         "lights.0.shadow_resolution", "100.5", "whole number"},
        {"shadow softness",
         "lights:\n  - type: directional\n    direction: [0, -1, 0]\n"
         "    shadow_softness: 9\n" +
             objects,
         "lights.0.shadow_softness", "9\n", "between 0 and 8"},
        {"shadow bias",
         "lights:\n  - type: directional\n    direction: [0, -1, 0]\n"
         "    shadow_bias: -1\n" +
             objects,
         "lights.0.shadow_bias", "-1\n", "between 0 and 100"},
        {"shadows not a boolean",
         "lights:\n  - type: directional\n    direction: [0, -1, 0]\n"
         "    shadows: soft\n" +
             objects,
         "lights.0.shadows", "soft", "true or false"},
        {"spot direction zero", kSpot + "    direction: [0, 0, 0]\n" + objects,
         "lights.0.direction", "[0, 0, 0]", "[0, 0, 0]"},
    });
}

TEST_CASE("light keys that do not apply to the type are named with the type's keys",
          "[scene][errors][lights]") {
    const std::string objects = kMinimalObjects;
    run_error_cases({
        {"ambient with a direction",
         "lights:\n  - type: ambient\n    direction: [0, -1, 0]\n" + objects, "lights.0.direction",
         "[0, -1, 0]", "does not apply to an ambient light (its keys are: type, color, intensity)"},
        {"ambient with shadows", "lights:\n  - type: ambient\n    shadows: true\n" + objects,
         "lights.0.shadows", "true", "does not apply to an ambient light"},
        {"point with a cone",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n    outer_angle: 30\n" + objects,
         "lights.0.outer_angle", "30", "does not apply to a point light"},
        {"directional with a range",
         "lights:\n  - type: directional\n    direction: [0, -1, 0]\n    range: 3\n" + objects,
         "lights.0.range", "3\n", "does not apply to a directional light"},
        {"unknown light key", "lights:\n  - type: spot\n    cone: 30\n" + objects, "lights.0.cone",
         "cone", "unknown key"},
        {"unknown colour key",
         "lights:\n  - type: point\n    position: [0, 1, 0]\n    color: { kelvn: 3000 }\n" +
             objects,
         "lights.0.color.kelvn", "kelvn", "unknown key"},
        {"unknown light type", "lights:\n  - type: area\n" + objects, "lights.0.type", "area",
         "directional, point, spot, ambient"},
    });
}

TEST_CASE("missing light keys are reported at the light", "[scene][errors][lights]") {
    const std::string objects = kMinimalObjects;
    run_error_cases({
        {"spot without direction", kSpot + objects, "lights.0", "type",
         "missing required key 'direction'"},
        {"spot without position", "lights:\n  - type: spot\n    direction: [0, -1, 0]\n" + objects,
         "lights.0", "type", "missing required key 'position'"},
    });
}

TEST_CASE("object shadow flags and material aliases are checked", "[scene][errors][lights]") {
    run_error_cases({
        {"cast_shadows not a boolean", "objects:\n  - primitive: cube\n    cast_shadows: maybe\n",
         "objects.0.cast_shadows", "maybe", "true or false"},
        {"receive_shadows not a boolean", "objects:\n  - primitive: cube\n    receive_shadows: 2\n",
         "objects.0.receive_shadows", "2\n", "true or false"},
        {"ka and ambient both",
         "objects:\n  - primitive: cube\n    material: { ambient: 0.1, ka: 0.2 }\n",
         "objects.0.material.ka", "0.2", "'ka' and 'ambient'"},
        {"kd and diffuse both",
         "objects:\n  - primitive: cube\n    material: { kd: 0.5, diffuse: 0.6 }\n",
         "objects.0.material.kd", "0.5", "'kd' and 'diffuse'"},
        {"ks out of range", "objects:\n  - primitive: cube\n    material: { ks: -1 }\n",
         "objects.0.material.ks", "-1", "between 0 and 1000"},
    });
}
