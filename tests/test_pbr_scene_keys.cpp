// The `pbr` model's keys in a scene file (docs/pbr.md, "Material keys",
// "environment", "The pbr preset"): keyed metal and roughness, the maps a
// scene names (read as data or colour, with uv_scale and wrap), the errors
// that point at their key, the warnings for inputs another model drops,
// and what `style: pbr` changes by default. The files' own materials are
// in test_pbr_materials.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/texture.hpp"
#include "output/encoders.hpp"
#include "render/frame_inputs.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;
using json = nlohmann::json;

namespace {

// The slot's texture is read as numbers (byte / 255).
void require_data(const TextureSlot& slot) {
    REQUIRE(slot.texture);
    CHECK(slot.texture->format() == Texture::Format::data8);
    CHECK(slot.texture->texel(0, 0, 0).g == Approx(kMidByte / 255.0f).margin(1e-6));
}

// The slot's texture is read as sRGB colour (IEC 61966-2-1's decode).
void require_colour(const TextureSlot& slot) {
    REQUIRE(slot.texture);
    CHECK(slot.texture->format() == Texture::Format::srgb8);
    const float srgb = std::pow((kMidByte / 255.0f + 0.055f) / 1.055f, 2.4f);
    CHECK(slot.texture->texel(0, 0, 0).g == Approx(srgb).margin(1e-4));
}

// The material object `object` of the world draws first.
const Material& drawn_material(const World& world, uint32_t object) {
    const auto draw = std::find_if(world.draws.begin(), world.draws.end(),
                                   [&](const Draw& d) { return d.object == object; });
    REQUIRE(draw != world.draws.end());
    return world.materials[draw->material];
}

// A scene of one cube with `material` under `style`, plus `extra` (top-level keys).
std::string cube_scene(const std::string& style, const std::string& material,
                       const std::string& extra = "") {
    return "output: { size: [32, 32], frames: 1-11 }\nstyle: " + style + "\n" + extra +
           "objects:\n  - name: box\n    primitive: cube\n    material: " + material + "\n";
}

// Whether some warning's key is `key` and its message holds `part`.
bool warned(const Warnings& warnings, const std::string& key, const std::string& part) {
    return std::any_of(warnings.begin(), warnings.end(), [&](const Warning& w) {
        return w.key == key && w.message.find(part) != std::string::npos;
    });
}

std::string all_warnings(const Warnings& warnings) {
    std::string all;
    for (const Warning& w : warnings) all += w.describe() + "\n";
    return all;
}

}  // namespace

// --- Material keys --------------------------------------------------------------

TEST_CASE("scene metallic and roughness follow their keys from frame to frame", "[pbr][scene]") {
    TempDir dir("pbr-scene");
    const SceneDesc scene = load(write_text(
        dir.file("keyed.yaml"), cube_scene("pbr",
                                           "{ metallic: { keys: { 1: 0, 11: 1 } }, "
                                           "roughness: { keys: { 1: 0.2, 11: 0.8 } } }")));
    const World world = build_world(scene);
    const StylePlan plan = plan_styles(scene);
    FrameEvaluator evaluator(scene, world, plan, 1);
    const uint32_t box = world.draws.at(0).material;
    // Linear keys (the default): halfway at frame 6.
    struct Expected {
        int frame;
        float metallic, roughness;
    };
    for (const Expected e :
         {Expected{1, 0.0f, 0.2f}, Expected{6, 0.5f, 0.5f}, Expected{11, 1.0f, 0.8f}}) {
        INFO("frame " << e.frame);
        const FrameInputs inputs = evaluator.evaluate(e.frame, 0);
        CHECK(inputs.materials[box].metallic == Approx(e.metallic).margin(1e-6));
        CHECK(inputs.materials[box].roughness == Approx(e.roughness).margin(1e-6));
    }
    // The world keeps the first key; frames apply the rest.
    CHECK(world.materials[box].roughness == Approx(0.2f));
}

TEST_CASE("scene maps resolve against the scene's folder, data maps read numbers, emission colour",
          "[pbr][scene]") {
    TempDir dir("pbr-scene");
    for (const char* name : {"normal", "occlusion", "metal_rough", "glow", "shared"})
        write_bytes(dir.file(std::string("maps/") + name + ".png"), flat_png(kMidByte));
    const std::string path = write_text(
        dir.file("scene/maps.yaml"),
        cube_scene("pbr",
                   "{ normal_map: ../maps/normal.png, normal_scale: 0.5, "
                   "occlusion_map: ../maps/occlusion.png, occlusion_strength: 0.25, "
                   "metal_rough_map: ../maps/metal_rough.png, emissive_map: ../maps/glow.png }"));
    const SceneDesc scene = load(path);
    const MaterialDesc& desc = scene.objects.at(0).material;
    REQUIRE(desc.normal_map);
    CHECK(desc.normal_map->path == dir.file("maps/normal.png"));
    const World world = build_world(scene);
    INFO(all_warnings(world.warnings));
    const Material& m = drawn_material(world, 0);
    require_data(m.normal_map);
    require_data(m.occlusion_map);
    require_data(m.metal_rough_map);
    require_colour(m.emissive_map);
    CHECK(m.normal_scale == 0.5f);
    CHECK(m.occlusion_strength == 0.25f);
    // An emissive map alone glows: emissive becomes 1 for it to multiply.
    CHECK(m.emissive == glm::vec3(1.0f));

    SECTION("a given emissive colour is kept under the map") {
        const SceneDesc tinted = load(write_text(
            dir.file("scene/tinted.yaml"),
            cube_scene("pbr", "{ emissive: [0.5, 0.25, 0], emissive_map: ../maps/glow.png }")));
        CHECK(drawn_material(build_world(tinted), 0).emissive == glm::vec3(0.5f, 0.25f, 0.0f));
    }
    SECTION("one file as colour and as normal map gives two textures") {
        const SceneDesc shared = load(write_text(
            dir.file("scene/shared.yaml"),
            cube_scene("pbr", "{ texture: ../maps/shared.png, normal_map: ../maps/shared.png }")));
        const World shared_world = build_world(shared);
        const Material& s = drawn_material(shared_world, 0);
        require_colour(s.base_color_map);
        require_data(s.normal_map);
    }
}

TEST_CASE("uv_scale and wrap apply to every map, the file's specular and coat maps too",
          "[pbr][scene]") {
    TempDir dir("pbr-scene");
    write_bytes(dir.file("grey.png"), flat_png(kMidByte));
    // A glTF quad with a texture in each of its nine map slots.
    Gltf g;
    g.doc["images"] = {{{"uri", "data:image/png;base64," + base64(flat_png(kMidByte))}}};
    g.doc["textures"] = {{{"source", 0}}};
    const json slot = {{"index", 0}};
    g.doc["materials"] = {
        {{"pbrMetallicRoughness", {{"baseColorTexture", slot}, {"metallicRoughnessTexture", slot}}},
         {"normalTexture", slot},
         {"occlusionTexture", slot},
         {"emissiveFactor", {1, 1, 1}},
         {"emissiveTexture", slot},
         {"extensions",
          {{"KHR_materials_specular", {{"specularTexture", slot}, {"specularColorTexture", slot}}},
           {"KHR_materials_clearcoat",
            {{"clearcoatFactor", 1},
             {"clearcoatTexture", slot},
             {"clearcoatRoughnessTexture", slot}}}}}}};
    g.one_quad_scene();
    g.write(dir.file("coated.gltf"));
    const std::string text =
        "output: { size: [32, 32] }\nstyle: pbr\nobjects:\n"
        "  - name: coated\n    mesh: coated.gltf\n"
        "    material: { uv_scale: [2, 3], wrap: clamp }\n"
        "  - name: box\n    primitive: cube\n"
        "    material: { uv_scale: 4, wrap: mirror, texture: grey.png, normal_map: grey.png,\n"
        "                occlusion_map: grey.png, metal_rough_map: grey.png, emissive_map: "
        "grey.png }\n";
    const World world = build_world(load(write_text(dir.file("scaled.yaml"), text)));
    INFO(all_warnings(world.warnings));
    auto require_mapped = [](const TextureSlot& s, glm::vec2 scale, Wrap wrap) {
        REQUIRE(s.texture);
        // (0.5, 0.5) lands at the scale's multiple of it.
        const glm::vec2 uv = s.map({0.5f, 0.5f});
        CHECK(uv.x == Approx(0.5f * scale.x));
        CHECK(uv.y == Approx(0.5f * scale.y));
        CHECK(s.texture->sampler.wrap_s == wrap);
        CHECK(s.texture->sampler.wrap_t == wrap);
    };
    const Material& coated = drawn_material(world, 0);
    int slot_number = 0;
    for (const TextureSlot* s :
         {&coated.base_color_map, &coated.metal_rough_map, &coated.normal_map,
          &coated.occlusion_map, &coated.emissive_map, &coated.specular_weight_map,
          &coated.specular_color_map, &coated.clearcoat_map, &coated.clearcoat_roughness_map}) {
        INFO("glTF slot " << slot_number++);
        require_mapped(*s, {2, 3}, Wrap::clamp);
    }
    const Material& box = drawn_material(world, 1);
    slot_number = 0;
    for (const TextureSlot* s : {&box.base_color_map, &box.normal_map, &box.occlusion_map,
                                 &box.metal_rough_map, &box.emissive_map}) {
        INFO("scene slot " << slot_number++);
        require_mapped(*s, {4, 4}, Wrap::mirror);
    }
}

// --- Errors -------------------------------------------------------------------

TEST_CASE("scene sheen_color and sheen_roughness set the sheen, over a file's too",
          "[pbr][scene]") {
    TempDir dir("pbr-scene");
    const SceneDesc scene = load(
        write_text(dir.file("velvet.yaml"),
                   cube_scene("pbr", "{ sheen_color: [0.8, 0.1, 0.2], sheen_roughness: 0.7 }")));
    const World world = build_world(scene);
    const Material& m = drawn_material(world, 0);
    CHECK(m.sheen_color == glm::vec3(0.8f, 0.1f, 0.2f));
    CHECK(m.sheen_roughness == Approx(0.7f));
    // '#rrggbb' is sRGB, like every colour key.
    const SceneDesc hex =
        load(write_text(dir.file("hex.yaml"), cube_scene("pbr", "{ sheen_color: '#ffffff' }")));
    CHECK(drawn_material(build_world(hex), 0).sheen_color == glm::vec3(1.0f));
}

TEST_CASE("bad pbr keys are errors naming the file, line, column and key", "[pbr][scene]") {
    struct ErrorCase {
        const char* name;
        std::string text;
        std::string key;     // the dotted key the message quotes
        std::string needle;  // the text the position points at
        std::string says;
    };
    const std::string cube = "objects:\n  - primitive: cube\n";
    const std::vector<ErrorCase> cases = {
        {"normal_scale without normal_map", cube + "    material: { normal_scale: 2 }\n",
         "objects.0.material.normal_scale", "2 }", "give `normal_map:` too"},
        {"metallic above 1", cube + "    material: { metallic: 2 }\n",
         "objects.0.material.metallic", "2 }", "between 0 and 1"},
        {"sheen_roughness above 1", cube + "    material: { sheen_roughness: 3 }\n",
         "objects.0.material.sheen_roughness", "3 }", "between 0 and 1"},
        {"sheen_color of two numbers", cube + "    material: { sheen_color: [1, 0] }\n",
         "objects.0.material.sheen_color", "[1, 0]", "3"},
        {"roughness keyed above 1",
         cube + "    material: { roughness: { keys: { 1: 0.5, 9: 1.5 } } }\n",
         "objects.0.material.roughness.keys.9", "1.5", "between 0 and 1"},
        {"a missing map file", cube + "    material: { occlusion_map: nowhere/ao.png }\n",
         "objects.0.material.occlusion_map", "nowhere/ao.png", "ao.png"},
        {"environment file and colour", "environment: { file: x.hdr, color: [1, 1, 1] }\n" + cube,
         "environment.color", "[1, 1, 1]", "give only one of them"},
        {"an unknown environment name", "environment: bogus\n" + cube, "environment", "bogus",
         "studio"},
        {"background blur above 1", "environment: { background: { blur: 3 } }\n" + cube,
         "environment.background.blur", "3 }", "between 0 and 1"},
        {"follow_camera not a boolean", "environment: { follow_camera: often }\n" + cube,
         "environment.follow_camera", "often", "true"},
    };
    for (const ErrorCase& c : cases) {
        DYNAMIC_SECTION(c.name) {
            TempDir dir("pbr-scene-error");
            const std::string path = write_text(dir.file("bad.yaml"), c.text);
            const std::string message = load_error(path);
            check_error_at(message, path, line_col(c.text, c.needle), c.key);
            CHECK_THAT(message, Contains(c.says));
        }
    }
}

TEST_CASE("a scene map or environment file that cannot be read names its key", "[pbr][scene]") {
    TempDir dir("pbr-scene");
    write_text(dir.file("notes.png"), "not an image\n");
    write_text(dir.file("studio.hdr"), "not a radiance image either\n");
    SECTION("a normal map that is not an image") {
        const std::string text = cube_scene("pbr", "{ normal_map: notes.png }");
        const std::string path = write_text(dir.file("map.yaml"), text);
        const SceneDesc scene = load(path);
        require_input_error([&] { build_world(scene); }, path + ":" + line_col(text, "notes.png") +
                                                             ": 'objects.0.material.normal_map': ");
        require_input_error([&] { build_world(scene); }, "notes.png");
    }
    SECTION("an environment file that is not an HDR image") {
        const std::string text = cube_scene("pbr", "{}", "environment: { file: studio.hdr }\n");
        const std::string path = write_text(dir.file("environment.yaml"), text);
        const SceneDesc scene = load(path);
        require_input_error([&] { build_world(scene); },
                            path + ":" + line_col(text, "studio.hdr") + ": 'environment.file': ");
        // The command line refuses it as invalid input, naming the file and key.
        const RunResult run = run_facet("validate '" + path + "'");
        INFO(run.output);
        CHECK(run.exit_code == 2);
        CHECK_THAT(run.output, Contains("studio.hdr"));
        CHECK_THAT(run.output, Contains("'environment.file'"));
    }
}

// --- Warnings -------------------------------------------------------------------

TEST_CASE(
    "pbr maps, a sheen, a film, an anisotropy or a diffuse transmission under blinn-phong warn "
    "that they are lost",
    "[pbr][warnings]") {
    TempDir dir("pbr-scene");
    write_bytes(dir.file("bump.png"), flat_png(kMidByte));
    const std::string material = "{ normal_map: bump.png, occlusion_map: bump.png }";
    const World phong =
        build_world(load(write_text(dir.file("phong.yaml"), cube_scene("blinn-phong", material))));
    INFO(all_warnings(phong.warnings));
    CHECK(warned(phong.warnings, "objects.0", "only `shading: pbr` draws"));
    CHECK(warned(phong.warnings, "objects.0", "its relief, occlusion"));
    CHECK(warned(phong.warnings, "objects.0", "'box'"));
    const World pbr =
        build_world(load(write_text(dir.file("pbr.yaml"), cube_scene("pbr", material))));
    INFO(all_warnings(pbr.warnings));
    CHECK_FALSE(warned(pbr.warnings, "objects.0", "only `shading: pbr` draws"));
    // Metal and roughness alone become a Phong highlight: nothing to warn of.
    const World factors = build_world(load(write_text(
        dir.file("factors.yaml"), cube_scene("blinn-phong", "{ metallic: 1, roughness: 0.2 }"))));
    CHECK_FALSE(warned(factors.warnings, "objects.0", "only `shading: pbr` draws"));
    // So is a metal-rough map: the Phong family reads it (docs/styles.md).
    const World metal_map = build_world(load(write_text(
        dir.file("metal_map.yaml"),
        cube_scene("blinn-phong", "{ metallic: 1, roughness: 0.5, metal_rough_map: bump.png }"))));
    CHECK_FALSE(warned(metal_map.warnings, "objects.0", "only `shading: pbr` draws"));
    // A metal-rough map alone makes a metallic-roughness material too.
    const World map_alone = build_world(load(write_text(
        dir.file("map_alone.yaml"), cube_scene("blinn-phong", "{ metal_rough_map: bump.png }"))));
    CHECK_FALSE(warned(map_alone.warnings, "objects.0", "only `shading: pbr` draws"));
    // `shininess` makes a Phong material, whose metal the Phong family does
    // not draw: that loss is named, and why.
    const World phong_metal =
        build_world(load(write_text(dir.file("phong_metal.yaml"),
                                    cube_scene("blinn-phong", "{ metallic: 1, shininess: 64 }"))));
    INFO(all_warnings(phong_metal.warnings));
    CHECK(warned(phong_metal.warnings, "objects.0", "'box' has metal, "));
    CHECK(warned(phong_metal.warnings, "objects.0", "occlusion, metal, specular"));
    CHECK(warned(phong_metal.warnings, "objects.0", "draws as a dielectric"));
    // A preset's own base colour replaces the material's on purpose.
    const World clay = build_world(load(
        write_text(dir.file("clay.yaml"), cube_scene("clay", "{ metallic: 1, shininess: 64 }"))));
    CHECK_FALSE(warned(clay.warnings, "objects.0", "only `shading: pbr` draws"));
    // A stylised model does not: there the map is lost, and the warning names metal.
    const World toon = build_world(load(write_text(
        dir.file("toon.yaml"),
        cube_scene("toon", "{ metallic: 1, roughness: 0.5, metal_rough_map: bump.png }"))));
    CHECK(warned(toon.warnings, "objects.0", "occlusion, metal, specular"));
    // A sheen, a thin film and an anisotropy are lost the same way.
    for (const char* lobe :
         {"{ sheen_color: [0.8, 0.1, 0.1] }", "{ iridescence: 0.6 }",
          "{ anisotropy: 0.5, anisotropy_rotation: 45 }",
          "{ diffuse_transmission: 0.5, diffuse_transmission_color: [1, 0.5, 0] }"}) {
        INFO(lobe);
        const World lost =
            build_world(load(write_text(dir.file("lobe.yaml"), cube_scene("blinn-phong", lobe))));
        CHECK(warned(lost.warnings, "objects.0", "film, anisotropy and light through it are lost"));
    }
}

TEST_CASE("an environment with no pbr style to light and no background warns", "[pbr][warnings]") {
    TempDir dir("pbr-scene");
    const std::string says = "lights only `shading: pbr` styles";
    auto warnings_of = [&](const std::string& style, const std::string& environment,
                           const std::string& object_extra = "") {
        const std::string text = "output: { size: [32, 32] }\nstyle: " + style +
                                 "\nenvironment: " + environment +
                                 "\nobjects:\n  - primitive: cube\n" + object_extra;
        return build_world(load(write_text(dir.file("environment.yaml"), text))).warnings;
    };
    const Warnings unlit = warnings_of("blinn-phong", "{ color: [1, 1, 1] }");
    INFO(all_warnings(unlit));
    CHECK(warned(unlit, "environment", says));
    CHECK(warned(warnings_of("toon", "studio"), "environment", says));
    // Shown as the background, lighting a pbr style, lighting one pbr
    // object, or none at all: no warning.
    CHECK_FALSE(warned(warnings_of("blinn-phong", "{ color: [1, 1, 1], background: true }"),
                       "environment", says));
    CHECK_FALSE(warned(warnings_of("pbr", "{ color: [1, 1, 1] }"), "environment", says));
    CHECK_FALSE(warned(warnings_of("blinn-phong", "{ color: [1, 1, 1] }", "    style: pbr\n"),
                       "environment", says));
    CHECK_FALSE(warned(warnings_of("blinn-phong", "none"), "environment", says));
}

// --- The pbr preset -----------------------------------------------------------------

TEST_CASE("style pbr brings the neutral tone curve unless the scene gives one", "[pbr][preset]") {
    TempDir dir("pbr-scene");
    auto tonemap_of = [&](const std::string& style, const std::string& output) {
        const std::string text = "output: " + output + "\nstyle: " + style + "\n" + kMinimalObjects;
        return load(write_text(dir.file("tonemap.yaml"), text)).output.display.tonemap;
    };
    CHECK(tonemap_of("pbr", "{ size: [32, 32] }") == Tonemap::neutral);
    CHECK(tonemap_of("pbr", "{ size: [32, 32], tonemap: none }") == Tonemap::none);
    CHECK(tonemap_of("pbr", "{ size: [32, 32], tonemap: aces }") == Tonemap::aces);
    CHECK(tonemap_of("blinn-phong", "{ size: [32, 32] }") != Tonemap::neutral);
}

TEST_CASE("without lights, the default key light is half as strong under pbr", "[pbr][preset]") {
    TempDir dir("pbr-scene");
    auto lights_of = [&](const std::string& style, const std::string& lights = "") {
        const std::string text =
            "output: { size: [32, 32] }\nstyle: " + style + "\n" + lights + kMinimalObjects;
        return load(write_text(dir.file("lights.yaml"), text)).lights;
    };
    const std::vector<LightDesc> pbr = lights_of("pbr");
    REQUIRE(pbr.size() == 1);
    CHECK(pbr[0].intensity.value == 0.5f);
    // The preset's shadows reach the default light.
    CHECK(pbr[0].shadows);
    const std::vector<LightDesc> phong = lights_of("blinn-phong");
    REQUIRE(phong.size() == 1);
    CHECK(phong[0].intensity.value == 1.0f);
    CHECK(phong[0].direction.value == pbr[0].direction.value);
    // Lights the scene gives keep their intensity under pbr.
    const std::vector<LightDesc> given =
        lights_of("pbr", "lights: [{ type: directional, direction: [0, -1, 0], intensity: 1 }]\n");
    REQUIRE(given.size() == 1);
    CHECK(given[0].intensity.value == 1.0f);
}
