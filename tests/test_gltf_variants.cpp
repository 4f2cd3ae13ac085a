// KHR_materials_variants: a product's colourways. The file's variants are
// read (facet info lists them), `variant:` or --variant draws one, `all`
// renders each into a folder of its own with a manifest naming it, and
// files that map what they do not have are refused naming the key.
// Every file is made here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "core/half.hpp"
#include "gltf_quad_support.hpp"
#include "job/render_job.hpp"
#include "render/world.hpp"
#include "render_check.hpp"
#include "scene_support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The quad's materials, unlit, in file order: red (its own), green, blue.
const std::vector<glm::vec3> kColors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

// The file's variants: "sunrise" maps the quad to green, "midnight" to
// blue, and "plain" maps it to nothing, so it keeps its red.
const json kMappings =
    json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}});

// The quad facing the camera of framing_scene, with the materials above,
// the variants and `mappings` as its primitive's.
std::string variant_quad(const std::string& path, const json& mappings = kMappings) {
    Gltf g;
    for (size_t m = 0; m < kColors.size(); ++m) {
        const glm::vec3 c = kColors[m];
        g.doc["materials"].push_back(
            {{"name", std::vector<std::string>{"red", "green", "blue"}[m]},
             {"pbrMetallicRoughness", {{"baseColorFactor", {c.r, c.g, c.b, 1}}}},
             {"extensions", {{"KHR_materials_unlit", json::object()}}}});
    }
    g.one_quad_scene();
    g.doc["meshes"][0]["primitives"][0]["extensions"] = {
        {"KHR_materials_variants", {{"mappings", mappings}}}};
    g.doc["extensions"] = {
        {"KHR_materials_variants",
         {{"variants", {{{"name", "sunrise"}}, {{"name", "midnight"}}, {{"name", "plain"}}}}}}};
    g.doc["extensionsUsed"] = {"KHR_materials_unlit", "KHR_materials_variants"};
    return g.write(path);
}

// The scene of the quad alone (`extra`: keys after its objects), written
// into `dir` as variants.yaml.
std::string quad_scene(const TempDir& dir, const std::string& extra = "") {
    const std::string mesh = variant_quad(dir.file("quad.gltf"));
    return write_text(dir.file("variants.yaml"), framing_scene(mesh, extra));
}

struct Drawn {
    glm::vec3 color;
    uint32_t material_id, object_id;
};

// What the centre pixel of frame 1 shows under `overrides` (-D values).
Drawn drawn_at_centre(const std::string& scene_path, std::vector<Override> overrides) {
    SceneOptions options = with_styles();
    overrides.push_back({"output.passes", "[color, object_id, material_id]", "test"});
    options.overrides = overrides;
    const FrameImages images = render_images(load(scene_path, options));
    const int x = images.color.width / 2, y = images.color.height / 2;
    return {glm::vec3(to_float(images.color.at(x, y))), images.surface.material_id.at(x, y),
            images.surface.object_id.at(x, y)};
}

// Every regular file under `dir`, relative to it, sorted.
std::vector<std::string> files_under(const std::string& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out.push_back(fs::relative(e.path(), dir).string());
    std::sort(out.begin(), out.end());
    return out;
}

json read_json(const std::string& path) {
    return json::parse(read_file(path));
}

RunResult render(const std::string& scene, const std::string& out, const std::string& args) {
    return run_facet("render '" + scene + "' -o '" + out + "' --threads 1 -q " + args);
}

}  // namespace

TEST_CASE("a glTF file's variants are read: their names, and each part's material under each",
          "[gltf][variants]") {
    TempDir dir("gltf-variants");
    const auto mesh = std::make_shared<const Mesh>(load_gltf(variant_quad(dir.file("q.gltf"))));
    CHECK(mesh->variants == std::vector<std::string>{"sunrise", "midnight", "plain"});
    REQUIRE(mesh->parts.size() == 1);
    CHECK(mesh->parts[0].material == 0);
    CHECK(mesh->parts[0].variant_materials == std::vector<uint32_t>{1, 2, 0});
    // Read, not ignored: no warning names the extension.
    CHECK(mesh->extensions.ignored.empty());
    for (const Warning& w : mesh->warnings)
        CHECK_THAT(w.describe(), !Contains("KHR_materials_variants"));

    CHECK(with_variant(mesh, "midnight")->parts[0].material == 2);
    CHECK(with_variant(mesh, "sunrise")->parts[0].material == 1);
    // A variant that maps nothing here, or that the file lacks, keeps the
    // default material: the mesh itself.
    CHECK(with_variant(mesh, "plain") == mesh);
    CHECK(with_variant(mesh, "dusk") == mesh);
    CHECK(with_variant(mesh, "") == mesh);
}

TEST_CASE(
    "each variant draws its declared material in the colour, material-id and object-id passes",
    "[gltf][variants][render]") {
    TempDir dir("gltf-variants");
    const std::string scene = quad_scene(dir);
    const std::pair<std::string, uint32_t> cases[] = {
        {"", 0}, {"sunrise", 1}, {"midnight", 2}, {"plain", 0}};
    std::set<uint32_t> ids;
    for (const auto& [variant, material] : cases) {
        INFO("variant '" << variant << "'");
        std::vector<Override> overrides;
        if (!variant.empty()) overrides.push_back({"variant", variant, "test"});
        const Drawn drawn = drawn_at_centre(scene, overrides);
        require_vec3(drawn.color, kColors[material], 1e-3f);
        // The world lists the file's materials in its order: ids are the
        // same in every variant's run, and name the material drawn.
        CHECK(drawn.material_id == material + 1);
        CHECK(drawn.object_id == 1);
        ids.insert(drawn.material_id);
    }
    CHECK(ids.size() == 3);

    SECTION("the scene key chooses it too, and the command line's overrides it") {
        const std::string keyed = quad_scene(dir, "variant: midnight\n");
        require_vec3(drawn_at_centre(keyed, {}).color, kColors[2], 1e-3f);
        require_vec3(
            drawn_at_centre(keyed, {{"variant", "sunrise", "command line --variant"}}).color,
            kColors[1], 1e-3f);
    }
}

TEST_CASE("a model without the chosen variant keeps its own materials", "[gltf][variants]") {
    TempDir dir("gltf-variants");
    const std::string scene =
        quad_scene(dir,
                   "  - name: box\n    primitive: { type: cube, size: 0.5 }\n"
                   "    translate: [0, 0, -3]\n    material: { color: [0.2, 0.3, 0.4] }\n");
    SceneOptions options = with_styles();
    options.overrides = {{"variant", "midnight", "test"}};
    const World world = build_world(load(scene, options));
    std::map<uint32_t, glm::vec3> color_of_object;
    for (const Draw& d : world.draws) color_of_object[d.object] = world.materials[d.material].color;
    require_vec3(color_of_object.at(0), kColors[2]);
    require_vec3(color_of_object.at(1), {0.2f, 0.3f, 0.4f});
}

TEST_CASE("render --variant all writes a folder per variant, each manifest naming its variant",
          "[gltf][variants][cli]") {
    TempDir dir("gltf-variants");
    const std::string scene = quad_scene(dir);
    const std::string out = dir.file("out");
    const RunResult all = render(scene, out, "--variant all --passes color,material_id");
    INFO(all.output);
    REQUIRE(all.exit_code == 0);
    std::vector<std::string> expected;
    for (const char* variant : {"midnight", "plain", "sunrise"})
        for (const char* file : {"/color.0001.png", "/manifest.json", "/material_id.0001.png"})
            expected.push_back(std::string("variants/") + variant + file);
    CHECK(files_under(out) == expected);

    std::set<std::string> colour_hashes;
    json ids;
    for (const char* variant : {"sunrise", "midnight", "plain"}) {
        INFO(variant);
        const json m = read_json(out + "/variants/" + variant + "/manifest.json");
        CHECK(m.at("variant") == variant);
        CHECK(m.at("output_template") == "{scene}/{variant}/{pass}.{frame}.{ext}");
        for (const json& f : m.at("files"))
            if (f.at("pass") == "color") colour_hashes.insert(f.at("sha256").get<std::string>());
        // Every run names the same ids: the file's materials, in its order.
        if (ids.is_null()) ids = m.at("ids");
        CHECK(m.at("ids") == ids);
    }
    CHECK(colour_hashes.size() == 3);
    CHECK(ids.at("material_id").size() == 3);

    SECTION("one variant by name is the same image, with the manifest naming it") {
        const std::string one = dir.file("one");
        const RunResult run = render(scene, one, "--variant midnight --passes color,material_id");
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        CHECK(files_under(one) == std::vector<std::string>{"variants/color.0001.png",
                                                           "variants/manifest.json",
                                                           "variants/material_id.0001.png"});
        CHECK(read_file(one + "/variants/color.0001.png") ==
              read_file(out + "/variants/midnight/color.0001.png"));
        CHECK(read_json(one + "/variants/manifest.json").at("variant") == "midnight");
        // Another variant into that folder is another run's settings.
        const RunResult other = render(scene, one, "--variant sunrise");
        CHECK(other.exit_code == 2);
        CHECK_THAT(other.output, Contains("variant: 'midnight' there, 'sunrise' now"));
    }
    SECTION("a run of all again is the same run, with the same files") {
        const std::string before = read_file(out + "/variants/plain/manifest.json");
        const RunResult again = render(scene, out, "--variant all --passes color,material_id");
        INFO(again.output);
        CHECK(again.exit_code == 0);
        CHECK(files_under(out) == expected);
        CHECK(read_json(out + "/variants/plain/manifest.json").at("files") ==
              json::parse(before).at("files"));
    }
    SECTION("an output.path naming {variant} renders each without --variant") {
        const std::string named = dir.file("named");
        const std::string path = " -D 'output.path=\"{variant}/{frame}.{ext}\"'";
        const RunResult run = render(scene, named, path);
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        const std::vector<std::string> each = {"midnight/0001.png", "midnight/manifest.json",
                                               "plain/0001.png",    "plain/manifest.json",
                                               "sunrise/0001.png",  "sunrise/manifest.json"};
        CHECK(files_under(named) == each);
        CHECK(read_file(named + "/midnight/0001.png") ==
              read_file(out + "/variants/midnight/color.0001.png"));
        // One of them again, by name, into its folder: the same run's settings.
        const std::string plain = read_file(named + "/plain/manifest.json");
        const RunResult one = render(scene, named, "--variant plain" + path);
        INFO(one.output);
        CHECK(one.exit_code == 0);
        CHECK(files_under(named) == each);
        CHECK(read_json(named + "/plain/manifest.json").at("variant") == "plain");
        CHECK(read_json(named + "/plain/manifest.json").at("files") ==
              json::parse(plain).at("files"));
    }
    SECTION("an output.path that would put the variants' manifests in one folder is refused") {
        const RunResult run =
            render(scene, dir.file("flat"),
                   "--variant all -D 'output.path=\"{pass}_{variant}.{frame}.{ext}\"'");
        CHECK(run.exit_code == 2);
        CHECK_THAT(run.output,
                   Contains("'output.path'") && Contains("{variant} must name a folder"));
        CHECK_FALSE(fs::exists(dir.file("flat")));
    }
    SECTION("--dry-run lists every variant's files and manifest") {
        const RunResult run = run_facet("render '" + scene + "' -o '" + dir.file("dry") +
                                        "' --variant all --dry-run");
        CHECK(run.exit_code == 0);
        CHECK_THAT(run.output, Contains("variants/plain/color.0001.png") &&
                                   Contains("variants/sunrise/manifest.json") &&
                                   Contains("3 files and 3 manifests would be written"));
        CHECK_FALSE(fs::exists(dir.file("dry")));
    }
}

TEST_CASE("an unknown variant is a usage error that lists the file's variants",
          "[gltf][variants][cli]") {
    TempDir dir("gltf-variants");
    const std::string scene = quad_scene(dir);
    const RunResult run = render(scene, dir.file("out"), "--variant dusk");
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output,
               Contains("command line --variant dusk: 'variant': no model in the scene declares "
                        "the variant 'dusk' (variants: sunrise, midnight, plain, or all)"));
    CHECK_FALSE(fs::exists(dir.file("out")));
    const RunResult empty = render(scene, dir.file("out"), "--variant ''");
    CHECK(empty.exit_code == 2);
    CHECK_THAT(empty.output, Contains("command line --variant '': expected a variant's name or "
                                      "all, got an empty value"));
    // A movie is of one run's frames.
    const RunResult movie = render(scene, dir.file("out"), "--variant all --video m.mp4");
    CHECK(movie.exit_code == 2);
    CHECK_THAT(movie.output, Contains("3 variants each render their own: give --variant NAME"));
    CHECK_FALSE(fs::exists(dir.file("out")));

    SECTION("the scene key's error points at it") {
        const std::string text = read_file(quad_scene(dir, "variant: dusk\n"));
        const RunResult keyed = render(dir.file("variants.yaml"), dir.file("out"), "");
        CHECK(keyed.exit_code == 2);
        check_error_at(keyed.output, dir.file("variants.yaml"), line_col(text, "dusk"), "variant");
    }
    SECTION("the key is known to the scene reader, and a typo of it gets its name") {
        quad_scene(dir, "variants: dusk\n");
        const RunResult typo = render(dir.file("variants.yaml"), dir.file("out"), "");
        CHECK(typo.exit_code == 2);
        CHECK_THAT(typo.output, Contains("did you mean 'variant'"));
    }
    SECTION("all where no model has variants, and all where one is drawn at a time") {
        const std::string plain =
            write_text(dir.file("plain.yaml"), framing_scene(dir.file("quad.gltf")) +
                                                   "  - name: other\n    primitive: cube\n");
        const RunResult none =
            render(write_text(dir.file("cube.yaml"), "objects:\n  - primitive: cube\n"),
                   dir.file("out"), "--variant all");
        CHECK(none.exit_code == 2);
        CHECK_THAT(none.output, Contains("no model in the scene declares variants"));
        SceneOptions options = with_styles();
        options.overrides = {{"variant", "all", "command line --variant all"}};
        require_input_error([&] { build_world(load(plain, options)); },
                            "one variant at a time (render and validate take all); give one "
                            "of: sunrise, midnight, plain");
    }
}

TEST_CASE("variant mappings that name what the file lacks are refused with their key",
          "[gltf][variants][errors]") {
    TempDir dir("gltf-variants");
    const std::string prefix =
        "bad.gltf: mesh '' primitive 0: extensions.KHR_materials_variants.mappings";
    auto refused = [&](const json& mappings, const std::string& message) {
        const std::string file = variant_quad(dir.file("bad.gltf"), mappings);
        require_input_error([&] { load_gltf(file); }, message);
    };
    refused(json::array({{{"material", 1}, {"variants", {0, 7}}}}),
            prefix +
                "[0].variants[1] refers to missing variant 7 (the file declares 3 "
                "variants: 'sunrise', 'midnight', 'plain')");
    refused(
        json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 9}, {"variants", {1}}}}),
        prefix + "[1].material refers to missing material 9 (the file has 3 materials)");
    refused(
        json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {0}}}}),
        prefix + "[1].variants[0]: the variant 'sunrise' is mapped a second time");
    // Types are checked before anything is read, by their JSON path.
    const std::string at = "bad.gltf: meshes[0].primitives[0].extensions.KHR_materials_variants";
    refused(json::array({{{"material", 1}, {"variants", "sunrise"}}}),
            at + ".mappings[0].variants must be a list of indices");
    refused(json::array({{{"material", -1}, {"variants", {0}}}}),
            at + ".mappings[0].material must be an index");
    refused(json::array({{{"variants", {0}}}}), at + ".mappings[0].material must be present");
    refused(json::object(), at + ".mappings must be a list");

    SECTION("the file's list of variants") {
        const std::string path = variant_quad(dir.file("names.gltf"));
        json doc = read_json(path);
        doc["extensions"]["KHR_materials_variants"]["variants"][1]["name"] = 5;
        write_text(path, doc.dump());
        require_input_error([&] { load_gltf(path); },
                            "names.gltf: extensions.KHR_materials_variants.variants[1].name must "
                            "be a string");
        doc["extensions"]["KHR_materials_variants"] = {{"variant", json::array()}};
        write_text(path, doc.dump());
        require_input_error([&] { load_gltf(path); },
                            "names.gltf: extensions.KHR_materials_variants.variants must be "
                            "present");
    }
    SECTION("a name given twice is a warning: the second is never drawn") {
        const std::string path = variant_quad(dir.file("twice.gltf"));
        json doc = read_json(path);
        doc["extensions"]["KHR_materials_variants"]["variants"][2]["name"] = "sunrise";
        write_text(path, doc.dump());
        const Mesh mesh = load_gltf(path);
        REQUIRE(mesh.warnings.size() == 1);
        CHECK_THAT(mesh.warnings[0].describe(),
                   Contains("variants[2]: the variant 'sunrise' is named twice"));
    }
}

TEST_CASE("facet info lists the variants and the materials each draws", "[gltf][variants][cli]") {
    TempDir dir("gltf-variants");
    const std::string file = variant_quad(dir.file("quad.gltf"));
    const RunResult text = run_facet("info '" + file + "'");
    INFO(text.output);
    CHECK(text.exit_code == 0);
    CHECK_THAT(text.output,
               Contains("variants:   3 (render one with --variant NAME, each with all)\n"
                        "  - sunrise: green (material 1)\n"
                        "  - midnight: blue (material 2)\n"
                        "  - plain: red (material 0)\n"));
    CHECK_THAT(text.output, Contains("not read none"));
    const RunResult j = run_facet("info --json '" + file + "'");
    REQUIRE(j.exit_code == 0);
    const json info = json::parse(j.output);
    REQUIRE(info.at("variants").size() == 3);
    CHECK(info["variants"][1] ==
          json({{"name", "midnight"}, {"materials", {{{"index", 2}, {"name", "blue"}}}}}));
    CHECK(info["extensions"]["ignored"] == json::array());
}

TEST_CASE("a model's turntable is one per variant, and facet scene writes the key",
          "[gltf][variants][turntable]") {
    TempDir dir("gltf-variants");
    const std::string model = variant_quad(dir.file("quad.gltf"));
    const std::string out = dir.file("out");
    const RunResult run = render(model, out, "--variant all --frames 1 --size 32x24");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK(files_under(out) ==
          std::vector<std::string>{"quad/midnight/color.0001.png", "quad/midnight/manifest.json",
                                   "quad/plain/color.0001.png", "quad/plain/manifest.json",
                                   "quad/sunrise/color.0001.png", "quad/sunrise/manifest.json"});
    CHECK(read_json(out + "/quad/sunrise/manifest.json").at("variant") == "sunrise");

    const RunResult scene = run_facet("scene '" + model + "' --variant sunrise -q");
    INFO(scene.output);
    CHECK(scene.exit_code == 0);
    CHECK_THAT(scene.output, Contains("# The model's variants: sunrise, midnight, plain.") &&
                                 Contains("variant: \"sunrise\""));
    const RunResult unknown = run_facet("scene '" + model + "' --variant dusk -q");
    CHECK(unknown.exit_code == 2);
    CHECK_THAT(unknown.output, Contains("no model in the scene declares the variant 'dusk'"));
}
