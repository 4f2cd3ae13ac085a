// facet::load_scene on invalid scene files: each throws facet::Error (exit
// code 2) naming the file, the line and column of the offending text, and the
// dotted key (docs/scene-format.md).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using Catch::Contains;
using namespace facet::test;

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
            write_text(dir.file("model.blend"), "BLENDER");
            std::string path = write_text(dir.file("bad.yaml"), c.text);
            std::string message = load_error(path);
            check_error_at(message, path, line_col(c.text, c.needle, c.offset), c.key);
            CHECK_THAT(message, Contains(c.says));
        }
    }
}

}  // namespace

// ---------------------------------------------------------------------------
// Style presets that cannot be found or read

TEST_CASE("an unknown style preset name lists the available presets", "[scene][style]") {
    TempDir dir("scene");
    const std::string text = "style: toonish\n" + kMinimalObjects;
    std::string path = write_text(dir.file("s.yaml"), text);
    std::string message = load_error(path);
    check_error_at(message, path, line_col(text, "toonish"), "style");
    CHECK_THAT(message, Contains("toonish"));
    CHECK_THAT(message, Contains("available"));
    // Every preset file in the styles folder is named.
    int presets = 0;
    for (const auto& entry : std::filesystem::directory_iterator(facet::test::styles_dir())) {
        if (entry.path().extension() != ".yaml") continue;
        ++presets;
        CHECK_THAT(message, Contains(entry.path().stem().string()));
    }
    CHECK(presets > 0);
}

TEST_CASE("errors inside a style file name that file", "[scene][style]") {
    TempDir dir("scene");
    const std::string style_text = "description: broken\nshading: cartoon\n";
    std::string style_path = write_text(dir.file("looks/bad.yaml"), style_text);
    std::string path = write_text(dir.file("s.yaml"), "style: looks/bad.yaml\n" + kMinimalObjects);
    std::string message = load_error(path);
    check_error_at(message, style_path, line_col(style_text, "cartoon\n"), "shading");
    CHECK_THAT(message, Contains("cartoon"));
}

// ---------------------------------------------------------------------------
// Invalid scenes: each case names the key and where its text is.

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
    std::string path = write_text(dir.file("s.yaml"), "camera:\n  zoom: 2\n" + kMinimalObjects);
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
        {"position pass without exr", "output:\n  passes: [color, position]\n" + objects,
         "output.passes", "[color, position]", 0, "only as EXR: add exr to output.formats"},
        {"motion pass with png only", "output:\n  passes: [motion]\n  formats: [png]\n" + objects,
         "output.formats", "[png]", 0, "the motion pass is written only as EXR"},
        {"normals in an unknown space", "output:\n  normals: tangent\n" + objects, "output.normals",
         "tangent", 0, "world, camera"},
        {"tone curve unknown", "output:\n  tonemap: reinhard\n" + objects, "output.tonemap",
         "reinhard", 0, "none, aces, filmic, neutral, agx"},
        {"exposure out of range", "output:\n  exposure: 40\n" + objects, "output.exposure", "40", 0,
         "-20"},
        {"exr layout unknown", "output:\n  exr: layered\n" + objects, "output.exr", "layered", 0,
         "separate, multilayer"},
        {"exr compression misspelt", "output:\n  exr_compression: pizz\n" + objects,
         "output.exr_compression", "pizz", 0, "did you mean 'piz'"},
        {"exr compression of a pass misspelt",
         "output:\n  exr_compression: {color: zip, depth: nope}\n" + objects,
         "output.exr_compression.depth", "nope", 0, "none, rle, zips, zip, piz, dwaa"},
        {"exr compression of no pass", "output:\n  exr_compression: {colour: zip}\n" + objects,
         "output.exr_compression.colour", "colour", 0, "did you mean 'color'"},
        {"background a word", "output:\n  background: clear\n" + objects, "output.background",
         "clear", 0, "must be a colour"},
        {"no passes", "output:\n  passes: []\n" + objects, "output.passes", "[]", 0,
         "at least one pass"},
        {"unknown primitive", "objects:\n  - primitive: teapot\n", "objects.0.primitive", "teapot",
         0, "cube"},
        {"unknown light type", "lights:\n  - type: area\n    direction: [0, -1, 0]\n" + objects,
         "lights.0.type", "area", 0, "directional, point, spot, ambient"},
        {"unknown wrap", "objects:\n  - primitive: cube\n    material:\n      wrap: spiral\n",
         "objects.0.material.wrap", "spiral", 0, "repeat, clamp, mirror"},
        {"spin axis a word", "objects:\n  - primitive: cube\n    spin:\n      axis: w\n",
         "objects.0.spin.axis", "w\n", 0, "x, y, z"},
        {"object name a list", "objects:\n  - primitive: cube\n    name: [a, b]\n",
         "objects.0.name", "[a, b]", 0, "text"},
        {"frames a list", "output:\n  frames: [1, 2]\n" + objects, "output.frames", "[1, 2]", 0,
         "text"},
        {"shading unknown", "style:\n  shading: cartoon\n" + objects, "style.shading", "cartoon", 0,
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
        {"near beyond the default far", "camera:\n  near: 200\n" + objects, "camera.near", "200", 0,
         "must be greater than near (200)"},
        {"position equals target",
         "camera:\n  position: [1, 1, 1]\n  target: [1, 1, 1]\n" + objects, "camera", "position", 0,
         "same point"},
    });
}

TEST_CASE("mesh and texture files must exist", "[scene][errors]") {
    run_error_cases({
        {"missing mesh", "objects:\n  - mesh: models/missing.obj\n", "objects.0.mesh", "models/", 0,
         "missing.obj"},
        {"missing texture",
         "objects:\n  - primitive: cube\n    material:\n      texture: wood.png\n",
         "objects.0.material.texture", "wood.png", 0, "no such file"},
    });
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
        {"deeper indentation", "camera:\n  fov: 30\n   near: 1\n" + kMinimalObjects, "", "near: 1",
         4, "YAML syntax error"},
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

TEST_CASE("a mesh file of no format facet reads is an error naming the object's key",
          "[scene][errors][cli]") {
    facet::test::TempDir dir("scene-mesh-format");
    write_text(dir.file("model.blend"), "BLENDER-v300 not a mesh facet reads");
    const std::string scene =
        write_text(dir.file("s.yaml"), "objects:\n  - name: blend\n    mesh: model.blend\n");
    const facet::test::RunResult r = facet::test::run_facet("validate '" + scene + "'");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("s.yaml:3:11: 'objects.0.mesh'") &&
                             Contains("not a mesh format facet reads ('.blend'"));
}
