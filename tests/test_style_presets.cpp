// Style presets as a scene sees them (docs/styles.md): `extends:` chains,
// the order of the layers (preset < the scene's own keys < -D style.* <
// an object's own style), per-object styles, keyed values evaluated per
// frame, the shipped library, and the errors a user gets for bad styles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/frame_renderer.hpp"
#include "render/style_eval.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using Catch::Contains;
using facet::Override;
using facet::SceneDesc;
using facet::SceneOptions;
using facet::ShadingModel;
using facet::StyleDesc;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

// Presets written into a temporary styles folder: `base` sets several
// values, `child` extends it and changes one, `grandchild` extends `child`.
const char* kBase = R"(description: the base look
shading: palette
palette: [[0.1, 0.2, 0.3], [0.7, 0.6, 0.5]]
alpha: 0.3
beta: 0.7
cels: 3
outlines:
  silhouette: { width: 3, color: [0, 0, 1] }
)";
const char* kChild = "description: the child look\nextends: base\ncels: 5\n";
const char* kGrandchild = "description: the grandchild\nextends: child\nalpha: 0.9\n";

struct StyleDir {
    TempDir dir{"style-presets"};
    StyleDir() {
        write_text(dir.file("styles/base.yaml"), kBase);
        write_text(dir.file("styles/child.yaml"), kChild);
        write_text(dir.file("styles/grandchild.yaml"), kGrandchild);
    }
    std::string styles() const { return dir.file("styles"); }
    std::string scene(const std::string& text, const std::string& name = "s.yaml") const {
        return write_text(dir.file("scene/" + name), text);
    }
    SceneOptions options(std::vector<Override> overrides = {}) const {
        SceneOptions o;
        o.style_dirs = {styles()};
        o.overrides = std::move(overrides);
        return o;
    }
};

Override define(const std::string& path, const std::string& value) {
    return {path, value, "command line -D " + path + "=" + value};
}

const StyleDesc& object_style(const SceneDesc& scene, size_t index) {
    return scene.objects.at(index).style ? *scene.objects.at(index).style : scene.style;
}

bool same(const glm::vec3& a, const glm::vec3& b) {
    return close_to(a.x, b.x) && close_to(a.y, b.y) && close_to(a.z, b.z);
}

}  // namespace

TEST_CASE("a preset extending another overrides one value and inherits the rest", "[style]") {
    StyleDir d;
    SECTION("one level") {
        const StyleDesc s = load(d.scene("style: child\n" + kMinimalObjects), d.options()).style;
        CHECK(s.name == "child");
        CHECK(s.description == "the child look");
        CHECK(s.cels.value == 5);  // its own value
        CHECK(s.shading == ShadingModel::palette);
        CHECK(close_to(s.alpha.value, 0.3f));
        CHECK(close_to(s.beta.value, 0.7f));
        CHECK(same(s.cool.value, {0.1f, 0.2f, 0.3f}));
        CHECK(same(s.warm.value, {0.7f, 0.6f, 0.5f}));
        CHECK(s.outlines.silhouette.enabled);
        CHECK(s.outlines.silhouette.width.value == 3);
        CHECK(same(s.outlines.silhouette.color.value, {0, 0, 1}));
        CHECK(s.chain == std::vector<std::string>{"base"});
        // The base itself is unchanged by having been extended.
        const StyleDesc b = load(d.scene("style: base\n" + kMinimalObjects), d.options()).style;
        CHECK(b.cels.value == 3);
        CHECK(b.chain.empty());
    }
    SECTION("two levels: the chain lists the parents, nearest last") {
        const StyleDesc s =
            load(d.scene("style: grandchild\n" + kMinimalObjects), d.options()).style;
        CHECK(s.name == "grandchild");
        CHECK(s.chain == std::vector<std::string>{"base", "child"});
        CHECK(close_to(s.alpha.value, 0.9f));  // its own
        CHECK(s.cels.value == 5);              // from child
        CHECK(close_to(s.beta.value, 0.7f));   // from base
        CHECK(s.shading == ShadingModel::palette);
    }
    SECTION("extends by a path relative to the preset file") {
        write_text(d.dir.file("elsewhere/near.yaml"),
                   "description: near\nextends: ../styles/child.yaml\nbeta: 0.1\n");
        const StyleDesc s =
            load(d.scene("style: ../elsewhere/near.yaml\n" + kMinimalObjects), d.options()).style;
        CHECK(s.cels.value == 5);
        CHECK(close_to(s.alpha.value, 0.3f));
        CHECK(close_to(s.beta.value, 0.1f));
        CHECK(s.chain == std::vector<std::string>{"base", "child"});
    }
    SECTION("a shipped preset: toon-outline extends toon") {
        const StyleDesc s = load(d.scene("style: toon-outline\n" + kMinimalObjects)).style;
        const StyleDesc toon = load(d.scene("style: toon\n" + kMinimalObjects)).style;
        CHECK(s.chain == std::vector<std::string>{"toon"});
        CHECK(s.shading == ShadingModel::toon);
        REQUIRE(s.toon.bands.size() == toon.toon.bands.size());
        for (size_t i = 0; i < s.toon.bands.size(); ++i)
            CHECK(s.toon.bands[i].threshold == toon.toon.bands[i].threshold);
        CHECK(s.toon.shininess == toon.toon.shininess);
        CHECK(s.outlines.silhouette.enabled);
        CHECK_FALSE(toon.outlines.silhouette.enabled);
    }
}

TEST_CASE("style layers: preset < the scene's own keys < -D style.* < object style", "[style]") {
    StyleDir d;
    const std::string text = R"(style:
  extends: base
  cels: 6
objects:
  - name: plain
    primitive: cube
  - name: own
    primitive: sphere
    style: { cels: 2 }
)";
    const std::string path = d.scene(text);

    const SceneDesc scene = load(path, d.options());
    CHECK(scene.style.cels.value == 6);              // beats the preset's 3
    CHECK(close_to(scene.style.alpha.value, 0.3f));  // from the preset
    CHECK(scene.style.chain == std::vector<std::string>{"base"});
    CHECK_FALSE(scene.objects[0].style.has_value());  // the scene style as it is
    REQUIRE(scene.objects[1].style.has_value());
    CHECK(scene.objects[1].style->cels.value == 2);  // beats the scene's 6
    CHECK(close_to(scene.objects[1].style->alpha.value, 0.3f));

    const SceneDesc defined =
        load(path, d.options({define("style.cels", "8"), define("style.beta", "0.25")}));
    CHECK(defined.style.cels.value == 8);  // -D beats the scene's own key
    CHECK(close_to(defined.style.beta.value, 0.25f));
    CHECK(close_to(defined.style.alpha.value, 0.3f));
    REQUIRE(defined.objects[1].style.has_value());
    CHECK(defined.objects[1].style->cels.value == 2);              // the object beats -D
    CHECK(close_to(defined.objects[1].style->beta.value, 0.25f));  // ...and keeps the rest of -D
    CHECK(object_style(defined, 0).cels.value == 8);

    SECTION("-D style.* also changes a style given by name") {
        const std::string named = d.scene("style: child\n" + kMinimalObjects, "named.yaml");
        const StyleDesc s = load(named, d.options({define("style.cels", "7")})).style;
        CHECK(s.cels.value == 7);
        CHECK(close_to(s.alpha.value, 0.3f));
        CHECK(s.name == "child");
    }
    SECTION("-D style.* after -D style=NAME changes the named preset") {
        const std::string none = d.scene(kMinimalObjects, "none.yaml");
        const StyleDesc s =
            load(none, d.options({define("style", "base"), define("style.cels", "9")})).style;
        CHECK(s.name == "base");
        CHECK(s.shading == ShadingModel::palette);
        CHECK(s.cels.value == 9);
    }
}

TEST_CASE("an object's style by name or by mapping applies to that object only", "[style]") {
    StyleDir d;
    const std::string text = R"(style: base
objects:
  - name: floor
    primitive: plane
    style: { palette: [[1, 0, 0], [0, 1, 0]] }
  - name: box
    primitive: cube
    style: child
  - name: ball
    primitive: sphere
)";
    const SceneDesc scene = load(d.scene(text), d.options());
    // By mapping: the scene's style with the palette changed.
    const StyleDesc& floor = object_style(scene, 0);
    CHECK(same(floor.cool.value, {1, 0, 0}));
    CHECK(same(floor.warm.value, {0, 1, 0}));
    CHECK(floor.cels.value == 3);
    CHECK(floor.shading == ShadingModel::palette);
    // By name: a whole preset of its own.
    const StyleDesc& box = object_style(scene, 1);
    CHECK(box.name == "child");
    CHECK(box.cels.value == 5);
    CHECK(box.chain == std::vector<std::string>{"base"});
    // Untouched: the scene's.
    CHECK_FALSE(scene.objects[2].style.has_value());
    CHECK(same(scene.style.cool.value, {0.1f, 0.2f, 0.3f}));
}

TEST_CASE("an object's style reaches the rendered pixels of that object only", "[style][render]") {
    TempDir dir("style-object-render");
    // Unlit, camera straight down -z: left box in its material's blue, the
    // right box restyled to red by its own `style:`.
    const std::string path =
        write_text(dir.file("s.yaml"), R"(output: { size: [64, 32], background: [0, 0, 0, 1] }
style: unlit
camera: { position: [0, 0, 6], target: [0, 0, 0], fov: 20 }
objects:
  - name: left
    primitive: cube
    translate: [-1, 0, 0]
    material: { color: [0, 0, 1] }
  - name: right
    primitive: cube
    translate: [1, 0, 0]
    material: { color: [0, 0, 1] }
    style: { base_color: [1, 0, 0] }
)");
    const SceneDesc scene = load(path);
    const facet::World world = facet::build_world(scene);
    facet::ThreadPool pool(1);
    facet::FrameRenderer renderer(scene, world, pool);
    facet::FrameImages images;
    renderer.render(1, 0, images);
    // The cube centres land 15 pixels either side of the middle.
    const glm::vec4 left = facet::to_float(images.color.at(17, 16)),
                    right = facet::to_float(images.color.at(47, 16));
    CHECK(same(glm::vec3(left), {0, 0, 1}));
    CHECK(same(glm::vec3(right), {1, 0, 0}));
}

TEST_CASE("keyed cels in a style step through whole numbers frame by frame", "[style]") {
    TempDir dir("style-keys");
    const std::string path = write_text(dir.file("s.yaml"), R"(output: { frames: 1-10 }
style:
  shading: palette
  cels: { keys: { 1: 2, 10: 6 } }
objects:
  - primitive: cube
)");
    const SceneDesc scene = load(path);
    REQUIRE(scene.style.cels.animated());
    facet::TamCache tams;
    std::set<int> seen;
    int previous = 0;
    for (int frame = 1; frame <= 10; ++frame) {
        const facet::FrameTime at{static_cast<double>(frame), (frame - 1) / 24.0};
        const float raw = facet::evaluate(scene.style.cels, at);
        const int cels = facet::evaluate_style(scene.style, at, tams).palette.cels;
        INFO("frame " << frame << ", keyed value " << raw);
        CHECK(cels == static_cast<int>(std::lround(raw)));
        CHECK(cels >= previous);  // the keys rise, so the cels never fall
        previous = cels;
        seen.insert(cels);
        if (frame == 1) CHECK(cels == 2);
        if (frame == 10) CHECK(cels == 6);
    }
    CHECK(seen == std::set<int>{2, 3, 4, 5, 6});
    // Between keys the value itself is not whole: the rounding is what makes it so.
    CHECK(std::fabs(facet::evaluate(scene.style.cels, {5.0, 4 / 24.0}) - 3.7778f) < 1e-3f);
}

TEST_CASE("every shipped preset loads and describes itself", "[style]") {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(facet::test::styles_dir()))
        if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    CHECK(names.size() >= 19);
    for (const char* wanted :
         {"phong", "gouraud", "flat", "palette", "palette-seed", "gooch", "toon", "toon-outline",
          "hatching", "pencil", "ink", "blueprint", "clay", "wireframe", "depth", "normals"})
        CHECK(std::find(names.begin(), names.end(), wanted) != names.end());

    const auto listed = facet::list_style_presets({facet::test::styles_dir()});
    CHECK(listed.size() == names.size());
    TempDir dir("style-shipped");
    for (const std::string& name : names) {
        INFO("preset " << name);
        const std::string file = (fs::path(facet::test::styles_dir()) / (name + ".yaml")).string();
        StyleDesc s;
        REQUIRE_NOTHROW(s = facet::load_style_file(file, {facet::test::styles_dir()}));
        CHECK(s.name == name);
        CHECK_FALSE(s.description.empty());
        CHECK(s.description.find('\n') == std::string::npos);  // one line
        // ...and by name from a scene, as users pick it.
        const std::string scene =
            write_text(dir.file("s.yaml"), "style: " + name + "\n" + kMinimalObjects);
        CHECK(load(scene).style.shading == s.shading);
    }
}

TEST_CASE("the palette-seed preset and the palette model carry the seed-000 values", "[style]") {
    auto check_seed_values = [](const StyleDesc& s) {
        CHECK(same(s.cool.value, {0, 0, 0.4f}));
        CHECK(same(s.warm.value, {0.4f, 0.4f, 0}));
        CHECK(close_to(s.alpha.value, 0.2f));
        CHECK(close_to(s.beta.value, 0.6f));
        CHECK(close_to(s.ambient.value, 0.2f));
        CHECK(close_to(s.hatch_below.value, 0.5f));
        CHECK(!s.cels_keep_hue);
        CHECK(s.cels.value == 4);
    };
    // The model's own defaults are the seed's; the `palette` preset tunes them.
    check_seed_values(StyleDesc{});
    const StyleDesc s = facet::load_style_file(
        std::string(facet::test::styles_dir()) + "/palette-seed.yaml", {facet::test::styles_dir()});
    CHECK(s.shading == ShadingModel::palette);
    check_seed_values(s);
    CHECK(s.hatching.has_value());
    CHECK(s.hatching->additive);
}

// ---------------------------------------------------------------------------
// Errors: file:line:column (or the command line) and the key path.

TEST_CASE("an unknown style key names file, line, key and the likely one", "[style]") {
    StyleDir d;
    SECTION("in a preset file") {
        const std::string text = "description: typo\nshadng: toon\n";
        const std::string style = write_text(d.dir.file("styles/typo.yaml"), text);
        const std::string message =
            load_error(d.scene("style: typo\n" + kMinimalObjects), d.options());
        check_error_at(message, style, line_col(text, "shadng"), "shadng");
        CHECK_THAT(message, Contains("did you mean 'shading'"));
    }
    SECTION("inline in the scene, nested") {
        const std::string text =
            "style:\n  shading: toon\n  toon:\n    rim: { colour: [1, 1, 1] }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "colour"), "style.toon.rim.colour");
        CHECK_THAT(message, Contains("did you mean 'color'"));
    }
    SECTION("in an object's style") {
        const std::string text = "objects:\n  - primitive: cube\n    style: { cells: 3 }\n";
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "cells"), "objects.0.style.cells");
        CHECK_THAT(message, Contains("did you mean 'cels'"));
    }
}

TEST_CASE("bad style values name file, line and key", "[style]") {
    StyleDir d;
    SECTION("cels out of range") {
        const std::string text = "style:\n  shading: palette\n  cels: 65\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "65"), "style.cels");
        CHECK_THAT(message, Contains("between 0 and 64"));
    }
    SECTION("a keyed cels value out of range") {
        const std::string text = "style:\n  cels: { keys: { 1: 2, 10: -1 } }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        CHECK_THAT(message, Contains(path + ":" + line_col(text, "-1") + ":"));
        CHECK_THAT(message, Contains("between 0 and 64"));
    }
    SECTION("toon bands out of order") {
        const std::string text =
            "description: x\nshading: toon\ntoon:\n"
            "  bands: [[0.5, 1.0], [0.2, 0.5]]\n";
        const std::string style = write_text(d.dir.file("styles/bands.yaml"), text);
        const std::string message =
            load_error(d.scene("style: bands\n" + kMinimalObjects), d.options());
        check_error_at(message, style, line_col(text, "0.2"), "toon.bands.1.0");
        CHECK_THAT(message, Contains("increase"));
    }
    SECTION("an unknown hatching space") {
        const std::string text = "style: { hatching: { space: sideways } }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "sideways"), "style.hatching.space");
        CHECK_THAT(message, Contains("object"));  // the choices are listed
    }
    SECTION("a hatching exposure out of range") {
        const std::string text = "style: { hatching: { exposure: 12 } }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "12"), "style.hatching.exposure");
        CHECK_THAT(message, Contains("between -10 and 10"));
    }
    SECTION("a zero hatching axis") {
        const std::string text =
            "style: { hatching: { direction: axis, axis: [0, 0, 0] } }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "[0, 0, 0]"), "style.hatching.axis");
    }
    SECTION("an unknown shading model") {
        const std::string text = "style: { shading: cartoon }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "cartoon"), "style.shading");
        CHECK_THAT(message, Contains("toon"));  // the choices are listed
    }
}

TEST_CASE("extends errors: cycles and missing presets", "[style]") {
    StyleDir d;
    SECTION("two presets extending each other") {
        const std::string a_text = "description: a\nextends: loop-b\n";
        const std::string b_text = "description: b\nextends: loop-a\n";
        write_text(d.dir.file("styles/loop-a.yaml"), a_text);
        const std::string b = write_text(d.dir.file("styles/loop-b.yaml"), b_text);
        const std::string message =
            load_error(d.scene("style: loop-a\n" + kMinimalObjects), d.options());
        // Found while loading b, the second of the loop: at b's `extends:`.
        check_error_at(message, b, line_col(b_text, "loop-a"), "extends");
        CHECK_THAT(message, Contains("extends itself"));
        CHECK_THAT(message, Contains("loop-a.yaml"));
    }
    SECTION("a preset extending itself") {
        const std::string text = "extends: self\n";
        const std::string self = write_text(d.dir.file("styles/self.yaml"), text);
        const std::string message =
            load_error(d.scene("style: self\n" + kMinimalObjects), d.options());
        check_error_at(message, self, line_col(text, "self"), "extends");
        CHECK_THAT(message, Contains("extends itself"));
    }
    SECTION("extends a preset that does not exist, listing the ones that do") {
        const std::string text = "style: { extends: chlid }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "chlid"), "style.extends");
        CHECK_THAT(message, Contains("no style preset named 'chlid'"));
        for (const char* name : {"base", "child", "grandchild"})
            CHECK_THAT(message, Contains(name));
    }
    SECTION("extends a file that does not exist") {
        const std::string text = "style: { extends: ../nowhere/gone.yaml }\n" + kMinimalObjects;
        const std::string path = d.scene(text);
        const std::string message = load_error(path, d.options());
        check_error_at(message, path, line_col(text, "../nowhere"), "style.extends");
        CHECK_THAT(message, Contains("gone.yaml"));
    }
}

TEST_CASE("a bad -D style value names the command line, not the file", "[style]") {
    StyleDir d;
    const std::string path = d.scene("style: child\n" + kMinimalObjects);
    SECTION("not a number") {
        const std::string message = load_error(path, d.options({define("style.cels", "x")}));
        CHECK_THAT(message, Contains("command line -D style.cels=x"));
        CHECK_THAT(message, Contains("'style.cels'"));
        CHECK_THAT(message, Contains("must be a number"));
        CHECK_THAT(message, !Contains(path));
        CHECK_THAT(message, !Contains("child.yaml"));
    }
    SECTION("out of range") {
        const std::string message = load_error(path, d.options({define("style.cels", "100")}));
        CHECK_THAT(message, Contains("command line -D style.cels=100"));
        CHECK_THAT(message, Contains("between 0 and 64"));
    }
    SECTION("an unknown key") {
        const std::string message = load_error(path, d.options({define("style.cells", "4")}));
        CHECK_THAT(message, Contains("command line -D style.cells=4"));
        CHECK_THAT(message, Contains("did you mean 'cels'"));
    }
}
