// glTF textures as files hold them and what facet says about a file: WebP
// and AVIF images, images told by their bytes, KHR_texture_basisu with and
// without fallbacks, lost textures named with their materials, lights in
// lux and candela, and facet info saying what render will refuse
// (docs/scene-format.md, "glTF"). Every file is made here.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/image_decode.hpp"
#include "core/half.hpp"
#include "gltf_quad_support.hpp"
#include "render_check.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

// A smooth 64x64 gradient (a codec's easy case), as PNG.
ColorImage gradient_image() {
    ColorImage image(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            image.at(x, y) = {static_cast<float>(x) / 63, static_cast<float>(y) / 63, 0.5f, 1};
    return image;
}

// The quad with the gradient as its base colour, in a folder of its own
// with the PNG beside it.
std::string gradient_quad(const TempDir& dir) {
    write_png(dir.file("gradient.png"), gradient_image());
    Gltf g;
    g.doc["images"] = {{{"uri", "gradient.png"}}};
    g.doc["textures"] = {{{"source", 0}}};
    quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    return g.write(dir.file("gradient.gltf"));
}

ColorImage unlit_picture(const TempDir& dir, const std::string& file) {
    return to_float_image(
        render_yaml(dir.path(),
                    "output: { size: [64, 64], frames: \"1\" }\nstyle: unlit\n"
                    "camera: { position: [0, 0, 2], target: [0, 0, 0], fov: 53.130102354 }\n"
                    "objects:\n  - mesh: " +
                        file + "\n")
            .color);
}

}  // namespace

TEST_CASE("WebP and AVIF textures draw as their PNG originals, within the codec's loss",
          "[gltf][texture][tools]") {
    if (!have_command("gltf-transform")) FACET_SKIP(kNoGltfTransform);
    TempDir dir("gltf-webp");
    const std::string png = gradient_quad(dir);
    const ColorImage original = unlit_picture(dir, png);
    for (const std::string codec : {"webp", "avif"}) {
        INFO(codec);
        const std::string file = dir.file("gradient-" + codec + ".glb");
        const Mesh mesh = transformed(codec + " --quality 90", png, file);
        CHECK(mesh.warnings.empty());
        CHECK(uses(mesh, codec == "webp" ? "EXT_texture_webp" : "EXT_texture_avif"));
        CHECK(mesh.extensions.ignored.empty());
        REQUIRE(mesh.materials[0].base_color_map.texture != nullptr);
        CHECK(mesh.materials[0].base_color_map.texture->width == 64);
        // Lossy at quality 90: a few levels of 255 on average.
        const ColorImage picture = unlit_picture(dir, file);
        double sum = 0, most = 0;
        for (size_t i = 0; i < picture.pixels.size(); ++i) {
            const double d = glm::length(glm::vec3(picture.pixels[i] - original.pixels[i]));
            sum += d;
            most = std::max(most, d);
        }
        CHECK(sum / static_cast<double>(picture.pixels.size()) < 0.02);
        CHECK(most < 0.15);
    }
}

TEST_CASE("images are recognised by their bytes, not their names", "[gltf][texture]") {
    TempDir dir("gltf-bytes");
    const std::vector<uint8_t> png = png_bytes(palette_image());
    write_bytes(dir.file("looks-like.jpg"), png);
    Gltf g;
    g.doc["images"] = {{{"uri", "looks-like.jpg"}, {"mimeType", "image/jpeg"}}};
    g.doc["textures"] = {{{"source", 0}}};
    quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const Mesh mesh = load_gltf(g.write(dir.file("named.gltf")));
    CHECK(mesh.warnings.empty());
    REQUIRE(mesh.materials[0].base_color_map.texture != nullptr);
    CHECK(sniff_image(png.data(), png.size()) == ImageFormat::png);
    const std::vector<uint8_t> ktx2 = {0xab, 'K',  'T',  'X',  ' ',  '2', '0',
                                       0xbb, '\r', '\n', 0x1a, '\n', 0,   0};
    CHECK(sniff_image(ktx2.data(), ktx2.size()) == ImageFormat::ktx2);
    require_input_error([&] { decode_texture(ktx2.data(), ktx2.size(), "x.ktx2", nullptr); },
                        "x.ktx2: KTX2 (KHR_texture_basisu) images are not supported");
}

namespace {

// A texture whose KHR_texture_basisu source is a KTX2 image (image 1) and
// whose core source (image 0), when `fallback`, is a PNG.
std::string basisu_file(const TempDir& dir, bool fallback, bool required) {
    const std::vector<uint8_t> ktx2 = {0xab, 'K',  'T',  'X',  ' ', '2', '0', 0xbb,
                                       '\r', '\n', 0x1a, '\n', 0,   0,   0,   0};
    Gltf g;
    g.doc["images"] = {{{"uri", "data:image/png;base64," + base64(png_bytes(palette_image()))}},
                       {{"uri", "data:image/ktx2;base64," + base64(ktx2)}}};
    json texture = {{"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}};
    if (fallback) texture["source"] = 0;
    g.doc["textures"] = json::array({texture});
    quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    g.doc["extensionsUsed"] = {"KHR_texture_basisu"};
    if (required) g.doc["extensionsRequired"] = {"KHR_texture_basisu"};
    return g.write(dir.file(std::string("basisu") + (fallback ? "-fallback" : "") + ".gltf"));
}

}  // namespace

TEST_CASE("KHR_texture_basisu: the PNG fallback is drawn, with a warning", "[gltf][texture]") {
    TempDir dir("gltf-basisu");
    const Mesh mesh = load_gltf(basisu_file(dir, true, false));
    REQUIRE(mesh.materials[0].base_color_map.texture != nullptr);
    CHECK(mesh.materials[0].base_color_map.texture->width == 4);
    REQUIRE(mesh.warnings.size() == 1);
    CHECK_THAT(mesh.warnings[0].message, Contains("KHR_texture_basisu") && Contains("fallback"));
    CHECK(mesh.extensions.ignored == std::vector<std::string>{"KHR_texture_basisu"});
    // Required, with its fallback: still drawn (a warning).
    CHECK(load_gltf(basisu_file(dir, true, true)).materials[0].base_color_map.texture != nullptr);
    // Required, without one: refused, saying so.
    const std::string none = basisu_file(dir, false, true);
    require_input_error([&] { load_gltf(none); },
                        "texture 0: KTX2 (KHR_texture_basisu) is not supported; the file has no "
                        "PNG/JPEG fallback");
    // Used only, without one: that texture is lost, with a warning.
    const std::string used = basisu_file(dir, false, false);
    const Mesh lost = load_gltf(used);
    CHECK(lost.materials[0].base_color_map.texture == nullptr);
    bool warned = false;
    for (const Warning& w : lost.warnings)
        warned = warned || (w.message.find("baseColorTexture") != std::string::npos &&
                            w.message.find("no PNG/JPEG fallback") != std::string::npos);
    CHECK(warned);
}

TEST_CASE(
    "a missing texture is a warning naming the file, the material and the map, and "
    "--strict makes it an error",
    "[gltf][texture][cli]") {
    TempDir dir("gltf-missing");
    Gltf g;
    g.doc["images"] = {{{"uri", "paint.png"}}, {{"uri", "bumps.png"}}};
    g.doc["textures"] = {{{"source", 0}}, {{"source", 1}}};
    quad_mesh(g, {{"name", "Hull"},
                  {"pbrMetallicRoughness",
                   {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}, {"baseColorTexture", {{"index", 0}}}}},
                  {"normalTexture", {{"index", 1}}}});
    const std::string file = g.write(dir.file("ship.gltf"));
    const Mesh mesh = load_gltf(file);
    CHECK(mesh.materials[0].base_color_map.texture == nullptr);
    CHECK(mesh.materials[0].color == glm::vec3(0.2f, 0.4f, 0.6f));
    std::string all;
    for (const Warning& w : mesh.warnings) all += w.describe() + "\n";
    INFO(all);
    CHECK_THAT(all, Contains("ship.gltf: material 'Hull' baseColorTexture: 'paint.png'") &&
                        Contains("no such file; drawn without it"));
    CHECK_THAT(all, Contains("material 'Hull' normalTexture: 'bumps.png'") &&
                        Contains("drawn with the mesh's normals"));
    // The scene renders, and says what is lost.
    const std::string scene = write_text(dir.file("scene.yaml"), framing_scene("ship.gltf"));
    const RunResult run = run_facet("render '" + scene + "' -o '" + dir.file("out") + "'");
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.output, Contains("warning:") && Contains("paint.png"));
    // --strict: exit 2 before anything is written.
    const RunResult strict =
        run_facet("render '" + scene + "' --strict -o '" + dir.file("strict") + "'");
    CHECK(strict.exit_code == 2);
    CHECK_THAT(strict.output, Contains("--strict: 2 warnings are an error"));
    CHECK_FALSE(std::filesystem::exists(dir.file("strict")));
    CHECK(run_facet("validate '" + scene + "' --strict").exit_code == 2);
    CHECK(run_facet("validate '" + scene + "'").exit_code == 0);
}

TEST_CASE(
    "facet info shows what it can of any file and its extension lists, and says in render's "
    "words, with render's exit code, when render refuses it",
    "[gltf][cli]") {
    TempDir dir("gltf-info");
    Gltf g;
    g.doc["materials"] = {{{"name", "used"}}, {{"name", "unused"}}};
    g.one_node_scene(
        {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}, {"material", 0}});
    g.doc["extensionsUsed"] = {"KHR_animation_pointer", "EXT_lights_image_based",
                               "EXT_texture_webp"};
    g.doc["extensionsRequired"] = {"KHR_animation_pointer"};
    const std::string file = g.write(dir.file("needs.gltf"));
    require_input_error([&] { load_gltf(file); },
                        "requires the glTF extension KHR_animation_pointer");
    const RunResult render =
        run_facet("render '" + file + "' -f 1 --size 32x24 -o '" + dir.file("out") + "'");
    CHECK(render.exit_code == 2);
    const std::string refusal = render.output.substr(render.output.find("facet: error: "));
    const RunResult info =
        run_command("'" + facet_executable() + "' info --json '" + file + "' 2>" + dir.file("err"));
    INFO(info.output);
    CHECK(info.exit_code == 2);
    CHECK(read_file(dir.file("err")) == refusal);
    const json j = json::parse(info.output);
    CHECK(j["renders"] == false);
    CHECK_THAT(j["render_errors"].dump(),
               Contains("requires the glTF extension KHR_animation_pointer"));
    CHECK(j["triangles"] == 1);
    CHECK(j["extensions"]["used"] ==
          json::array({"KHR_animation_pointer", "EXT_lights_image_based", "EXT_texture_webp"}));
    CHECK(j["extensions"]["required"] == json::array({"KHR_animation_pointer"}));
    CHECK(j["extensions"]["ignored"] ==
          json::array({"KHR_animation_pointer", "EXT_lights_image_based"}));
    // Only the material a part uses; no unused "default".
    REQUIRE(j["materials"].size() == 1);
    CHECK(j["materials"][0]["name"] == "used");
    const RunResult text = run_facet("info '" + file + "'");
    CHECK(text.exit_code == 2);
    CHECK_THAT(text.output, Contains("not read KHR_animation_pointer, EXT_lights_image_based") &&
                                Contains(refusal));
}

TEST_CASE(
    "facet info of a file that requires KTX2 textures without fallbacks: render's error, and "
    "no texture 'drawn without it'",
    "[gltf][cli]") {
    TempDir dir("gltf-info-ktx2");
    Gltf g;
    g.doc["images"] = {{{"uri", "paint.ktx2"}}};
    g.doc["textures"] = {{{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}}};
    quad_mesh(g, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    g.doc["extensionsUsed"] = {"KHR_texture_basisu"};
    g.doc["extensionsRequired"] = {"KHR_texture_basisu"};
    write_text(dir.file("paint.ktx2"), "\xabKTX 20\xbb\r\n\x1a\n");
    const std::string file = g.write(dir.file("ktx2.gltf"));
    const RunResult render =
        run_facet("render '" + file + "' -f 1 --size 32x24 -o '" + dir.file("out") + "'");
    CHECK(render.exit_code == 2);
    const std::string refusal = render.output.substr(render.output.find("facet: error: "));
    const RunResult info = run_facet("info '" + file + "'");
    INFO(info.output);
    CHECK(info.exit_code == 2);
    CHECK_THAT(info.output, Contains(refusal) && !Contains("drawn without it"));
}

TEST_CASE("KHR_lights_punctual: lux and candela are lit as the Lambertian 1/pi says",
          "[gltf][lights]") {
    TempDir dir("gltf-light-units");
    // The quad lit head on by a file's sun of π lux, and by a scene sun of
    // intensity 1: the same colour.
    Gltf g;
    quad_mesh(g, json::object());
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    g.doc["extensions"] = {
        {"KHR_lights_punctual", {{"lights", {{{"type", "directional"}, {"intensity", M_PI}}}}}}};
    g.doc["scenes"][0]["nodes"].push_back(
        g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    const std::string file = g.write(dir.file("sun.gltf"));
    auto centre = [&](const std::string& lights, const std::string& object) {
        return to_float(
            render_yaml(dir.path(),
                        "output: { size: [16, 16], frames: \"1\" }\nstyle: lit\n" + lights +
                            "camera: { position: [0, 0, 2], target: [0, 0, 0], fov: 40 }\n"
                            "objects:\n  - mesh: sun.gltf\n    material: { specular: 0 }\n" +
                            object)
                .color.at(8, 8));
    };
    const glm::vec4 file_sun = centre("lights: []\n", "    lights: true\n");
    const glm::vec4 scene_sun =
        centre("lights:\n  - { type: directional, direction: [0, 0, -1] }\n", "");
    CHECK(file_sun.r > 0.1f);
    CHECK(file_sun.r == Approx(scene_sun.r).epsilon(1e-3));
}

TEST_CASE("every material that reads a lost texture says so", "[gltf][texture]") {
    TempDir dir("gltf-shared-lost");
    Gltf g;
    g.doc["images"] = {{{"uri", "gone.png"}}};
    g.doc["textures"] = {{{"source", 0}}};
    quad_mesh(
        g, {{"name", "First"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    g.doc["materials"].push_back(
        {{"name", "Second"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const Mesh mesh = load_gltf(g.write(dir.file("shared.gltf")));
    std::string all;
    for (const Warning& w : mesh.warnings) all += w.describe() + "\n";
    INFO(all);
    for (const char* material : {"'First'", "'Second'"})
        CHECK_THAT(
            all, Contains(std::string("material ") + material + " baseColorTexture: 'gone.png'") &&
                     Contains("no such file; drawn without it"));
}

TEST_CASE("what a glTF file holds that facet does not draw is named in a warning", "[gltf]") {
    TempDir dir("gltf-unread");
    auto warnings_of = [&](Gltf& g) {
        std::string all;
        for (const Warning& w : load_gltf(g.write(dir.file("unread.gltf"))).warnings)
            all += w.describe() + "\n";
        return all;
    };
    // Vertex colours with alpha below 1.
    Gltf colours;
    colours.one_node_scene(
        {{"attributes",
          {{"POSITION", colours.floats(kTriangle, "VEC3")},
           {"COLOR_0", colours.floats({1, 0, 0, 0.5f, 0, 1, 0, 1, 0, 0, 1, 1}, "VEC4")}}}});
    CHECK_THAT(warnings_of(colours), Contains("COLOR_0's alpha is not read"));
    // Opaque ones say nothing.
    Gltf opaque;
    opaque.one_node_scene(
        {{"attributes",
          {{"POSITION", opaque.floats(kTriangle, "VEC3")},
           {"COLOR_0", opaque.floats({1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1}, "VEC4")}}}});
    CHECK(warnings_of(opaque).empty());
    // A second scene.
    Gltf scenes;
    scenes.one_node_scene({{"attributes", {{"POSITION", scenes.floats(kTriangle, "VEC3")}}}});
    scenes.doc["scenes"].push_back({{"nodes", json::array({0})}});
    CHECK_THAT(warnings_of(scenes), Contains("has 2 scenes: scene 0 (the default) is drawn"));
}
