// The `pbr` model's material inputs as the mesh files give them
// (docs/pbr.md, "Material keys", "From files"): glTF's metallic-roughness
// factors and maps, KHR_materials_ior, _specular, _clearcoat and _sheen, the
// extensions facet leaves out, and MTL's PBR extension. Maps that hold
// numbers (normal, occlusion, metal-rough, ...) must read their bytes as
// byte / 255, not through the sRGB curve colour maps go through. Every file
// is made here; the scene's own keys are in test_pbr_scene_keys.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "assets/texture.hpp"
#include "output/encoders.hpp"
#include "render_check.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;
using json = nlohmann::json;

namespace {

// A byte as a number, as data maps read it.
float as_number(uint8_t byte) {
    return static_cast<float>(byte) / 255.0f;
}

// A byte as sRGB-encoded colour, decoded by the sRGB transfer function
// (IEC 61966-2-1), as colour maps read it.
float as_srgb_colour(uint8_t byte) {
    const double v = byte / 255.0;
    return static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

// A 2 x 2 quad facing +Z with normals and texture coordinates, showing
// material 0 of `materials`.
void quad_with_materials(Gltf& g, const json& materials) {
    g.doc["materials"] = materials;
    g.one_quad_scene();
}

// `count` textures, texture i showing image i, each a flat_png(kMidByte).
void mid_grey_textures(Gltf& g, int count) {
    for (int i = 0; i < count; ++i) {
        g.doc["images"].push_back({{"uri", "data:image/png;base64," + base64(flat_png(kMidByte))}});
        g.doc["textures"].push_back({{"source", i}});
    }
}

// A map's texel (0, 0) of level 0, where the slot has a texture.
glm::vec4 first_texel(const TextureSlot& slot) {
    REQUIRE(slot.texture);
    return slot.texture->texel(0, 0, 0);
}

// The slot reads mid-grey as the number 128/255, from a data texture.
void require_read_as_data(const TextureSlot& slot) {
    REQUIRE(slot.texture);
    CHECK(slot.texture->format() == Texture::Format::data8);
    const glm::vec4 t = first_texel(slot);
    for (int a = 0; a < 3; ++a) CHECK(t[a] == Approx(as_number(kMidByte)).margin(1e-6));
}

// The slot reads mid-grey as the colour it encodes in sRGB.
void require_read_as_colour(const TextureSlot& slot) {
    REQUIRE(slot.texture);
    CHECK(slot.texture->format() == Texture::Format::srgb8);
    const glm::vec4 t = first_texel(slot);
    for (int a = 0; a < 3; ++a) CHECK(t[a] == Approx(as_srgb_colour(kMidByte)).margin(1e-4));
}

// A quad whose material 0 is `material`, written to `name` in `dir` and loaded.
Mesh load_quad(const TempDir& dir, const json& material, const std::string& name = "m.gltf") {
    Gltf g;
    mid_grey_textures(g, 4);
    quad_with_materials(g, json::array({material}));
    return load_gltf(g.write(dir.file(name)));
}

}  // namespace

// --- glTF: the core metallic-roughness material ------------------------------

TEST_CASE("glTF metallicFactor and roughnessFactor are read, 1 and 1 when absent", "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    Gltf g;
    quad_with_materials(g, json::array({{{"name", "satin"},
                                         {"pbrMetallicRoughness",
                                          {{"metallicFactor", 0.25}, {"roughnessFactor", 0.75}}}},
                                        {{"name", "plain"}}}));
    const Mesh mesh = load_gltf(g.write(dir.file("factors.gltf")));
    REQUIRE(mesh.materials.size() == 2);
    CHECK(mesh.materials[0].metallic == 0.25f);
    CHECK(mesh.materials[0].roughness == 0.75f);
    // glTF 2.0 §5.22: both factors default to 1, a rough metal.
    CHECK(mesh.materials[1].metallic == 1.0f);
    CHECK(mesh.materials[1].roughness == 1.0f);
}

TEST_CASE("glTF factors out of 0..1 are refused, naming the file and the material", "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    struct Case {
        json pbr;
        std::string says;
    };
    for (const Case& c :
         {Case{{{"metallicFactor", 1.5}}, "metallicFactor must be from 0 to 1"},
          Case{{{"roughnessFactor", -0.1}}, "roughnessFactor must be from 0 to 1"}}) {
        INFO(c.says);
        Gltf g;
        quad_with_materials(g,
                            json::array({{{"name", "chrome"}, {"pbrMetallicRoughness", c.pbr}}}));
        const std::string path = g.write(dir.file("out-of-range.gltf"));
        require_input_error([&] { load_gltf(path); }, path + ": material 'chrome': " + c.says);
    }
}

TEST_CASE("glTF metallic-roughness, normal and occlusion maps are read as data with their factors",
          "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    const Mesh mesh =
        load_quad(dir, {{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 0}}}}},
                        {"normalTexture", {{"index", 1}, {"scale", 0.5}}},
                        {"occlusionTexture", {{"index", 2}, {"strength", 0.25}}}});
    INFO(all_warnings(mesh));
    const Material& m = mesh.materials.at(0);
    require_read_as_data(m.metal_rough_map);
    require_read_as_data(m.normal_map);
    require_read_as_data(m.occlusion_map);
    CHECK(m.normal_scale == 0.5f);
    CHECK(m.occlusion_strength == 0.25f);
    // Not the sRGB decode a colour map would give the same byte.
    CHECK(first_texel(m.normal_map).r > as_srgb_colour(kMidByte) + 0.2f);
    // Without them, the scale and strength keep glTF's defaults.
    const Mesh bare = load_quad(dir, json::object(), "bare.gltf");
    CHECK_FALSE(bare.materials[0].normal_map);
    CHECK(bare.materials[0].normal_scale == 1.0f);
    CHECK(bare.materials[0].occlusion_strength == 1.0f);
}

TEST_CASE("one glTF image used as colour and as data gives two textures, each read its way",
          "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    SECTION("two textures of one image") {
        Gltf g;
        mid_grey_textures(g, 1);
        g.doc["textures"].push_back({{"source", 0}});
        quad_with_materials(g, json::array({{{"pbrMetallicRoughness",
                                              {{"baseColorTexture", {{"index", 0}}},
                                               {"metallicRoughnessTexture", {{"index", 1}}}}}}}));
        const Mesh mesh = load_gltf(g.write(dir.file("shared-image.gltf")));
        require_read_as_colour(mesh.materials[0].base_color_map);
        require_read_as_data(mesh.materials[0].metal_rough_map);
    }
    SECTION("one texture in two slots") {
        const Mesh mesh =
            load_quad(dir, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                            {"emissiveFactor", {1, 1, 1}},
                            {"emissiveTexture", {{"index", 0}}},
                            {"occlusionTexture", {{"index", 0}}}});
        const Material& m = mesh.materials[0];
        require_read_as_colour(m.base_color_map);
        require_read_as_colour(m.emissive_map);
        require_read_as_data(m.occlusion_map);
        CHECK(m.base_color_map.texture != m.occlusion_map.texture);
    }
}

// --- glTF: the layer extensions ------------------------------------------------

TEST_CASE("KHR_materials_ior sets the index of refraction, refused outside 1..10", "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    const Mesh glass = load_quad(dir, {{"extensions", {{"KHR_materials_ior", {{"ior", 1.8}}}}}});
    CHECK(glass.materials[0].ior == Approx(1.8f));
    // An empty extension keeps glTF's 1.5.
    const Mesh plain =
        load_quad(dir, {{"extensions", {{"KHR_materials_ior", json::object()}}}}, "plain.gltf");
    CHECK(plain.materials[0].ior == 1.5f);
    for (const double ior : {0.0, 0.5, 10.5}) {
        INFO("ior " << ior);
        Gltf g;
        quad_with_materials(
            g, json::array(
                   {{{"name", "gem"}, {"extensions", {{"KHR_materials_ior", {{"ior", ior}}}}}}}));
        const std::string path = g.write(dir.file("bad-ior.gltf"));
        require_input_error([&] { load_gltf(path); },
                            path + ": material 'gem': ior must be from 1 to 10");
    }
}

TEST_CASE("KHR_materials_specular gives the reflectance's weight, tint and their maps",
          "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    const Mesh mesh = load_quad(dir, {{"extensions",
                                       {{"KHR_materials_specular",
                                         {{"specularFactor", 0.3},
                                          {"specularColorFactor", {0.5, 0.25, 1}},
                                          {"specularTexture", {{"index", 0}}},
                                          {"specularColorTexture", {{"index", 1}}}}}}}});
    INFO(all_warnings(mesh));
    const Material& m = mesh.materials[0];
    CHECK(m.specular_weight == Approx(0.3f));
    CHECK(m.specular_color == glm::vec3(0.5f, 0.25f, 1.0f));
    // The weight map's A is a number; the colour map is sRGB colour.
    require_read_as_data(m.specular_weight_map);
    require_read_as_colour(m.specular_color_map);
    // Without the extension: weight 1, white, no maps.
    const Mesh plain = load_quad(dir, json::object(), "plain.gltf");
    CHECK(plain.materials[0].specular_weight == 1.0f);
    CHECK(plain.materials[0].specular_color == glm::vec3(1.0f));
    CHECK_FALSE(plain.materials[0].specular_weight_map);
}

TEST_CASE("KHR_materials_clearcoat gives the coat and its maps, and its normal map warns",
          "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    const json coat = {{"clearcoatFactor", 0.7},
                       {"clearcoatRoughnessFactor", 0.2},
                       {"clearcoatTexture", {{"index", 0}}},
                       {"clearcoatRoughnessTexture", {{"index", 1}}}};
    const Mesh mesh = load_quad(dir, {{"extensions", {{"KHR_materials_clearcoat", coat}}}});
    INFO(all_warnings(mesh));
    const Material& m = mesh.materials[0];
    CHECK(m.clearcoat == Approx(0.7f));
    CHECK(m.clearcoat_roughness == Approx(0.2f));
    require_read_as_data(m.clearcoat_map);
    require_read_as_data(m.clearcoat_roughness_map);
    CHECK_FALSE(warns(mesh, "clearcoatNormalTexture"));

    CHECK_FALSE(m.clearcoat_normal_map);

    // The coat's own normal map is read as data with its scale (the test
    // below draws it, with tangent frames made though the base has no map).
    json with_normal = coat;
    with_normal["clearcoatNormalTexture"] = {{"index", 2}, {"scale", 0.6}};
    const Mesh relief = load_quad(
        dir, {{"name", "lacquer"}, {"extensions", {{"KHR_materials_clearcoat", with_normal}}}},
        "coat-normal.gltf");
    INFO(all_warnings(relief));
    CHECK_FALSE(warns(relief, "clearcoatNormalTexture"));
    require_read_as_data(relief.materials[0].clearcoat_normal_map);
    CHECK(relief.materials[0].clearcoat_normal_scale == Approx(0.6f));
    CHECK(relief.materials[0].clearcoat == Approx(0.7f));

    for (const char* field : {"clearcoatFactor", "clearcoatRoughnessFactor"}) {
        INFO(field);
        json out_of_range = coat;
        out_of_range[field] = 1.5;
        Gltf g;
        quad_with_materials(
            g, json::array({{{"name", "lacquer"},
                             {"extensions", {{"KHR_materials_clearcoat", out_of_range}}}}}));
        const std::string path = g.write(dir.file("bad-coat.gltf"));
        require_input_error([&] { load_gltf(path); },
                            path + ": material 'lacquer': " + field + " must be from 0 to 1");
    }
}

TEST_CASE("KHR_materials_sheen gives the sheen and its maps, and a black colour turns it off",
          "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    const json sheen = {{"sheenColorFactor", {0.9, 0.2, 0.1}},
                        {"sheenRoughnessFactor", 0.6},
                        {"sheenColorTexture", {{"index", 0}}},
                        {"sheenRoughnessTexture", {{"index", 1}}}};
    const Mesh mesh = load_quad(dir, {{"extensions", {{"KHR_materials_sheen", sheen}}}});
    INFO(all_warnings(mesh));
    CHECK(mesh.warnings.empty());
    const Material& m = mesh.materials[0];
    CHECK(m.sheen_color == glm::vec3(0.9f, 0.2f, 0.1f));
    CHECK(m.sheen_roughness == Approx(0.6f));
    require_read_as_colour(m.sheen_color_map);
    require_read_as_data(m.sheen_roughness_map);
    CHECK((m.features() & kPhysicalMaps) != 0);
    // A black colour (the default) is no sheen: its maps are not read.
    json black = sheen;
    black.erase("sheenColorFactor");
    const Mesh off = load_quad(dir, {{"extensions", {{"KHR_materials_sheen", black}}}}, "off.gltf");
    CHECK(off.materials[0].sheen_color == glm::vec3(0.0f));
    CHECK_FALSE(off.materials[0].sheen_color_map);
    CHECK_FALSE(off.materials[0].sheen_roughness_map);
    CHECK(off.materials[0].features() ==
          load_quad(dir, json::object(), "plain.gltf").materials[0].features());
    struct Bad {
        json sheen;
        std::string says;
    };
    for (const Bad& bad :
         {Bad{{{"sheenRoughnessFactor", 1.5}}, "sheenRoughnessFactor must be from 0 to 1"},
          Bad{{{"sheenColorFactor", {0.5, 2, 0}}},
              "sheenColorFactor must hold numbers from 0 to 1"},
          Bad{{{"sheenColorFactor", {0.5, 0.5}}},
              "KHR_materials_sheen.sheenColorFactor must be a list of 3 numbers"}}) {
        INFO(bad.says);
        Gltf g;
        quad_with_materials(
            g, json::array(
                   {{{"name", "velvet"}, {"extensions", {{"KHR_materials_sheen", bad.sheen}}}}}));
        const std::string path = g.write(dir.file("bad-sheen.gltf"));
        require_input_error([&] { load_gltf(path); }, bad.says);
    }
}

// A black, rough base under a smooth coat, lit from the camera's direction:
// the coat's mirror highlight fills the middle of the quad. A coat normal
// map tilted by 25 degrees turns it away (the light no longer reflects into
// the camera), a flat one keeps it, and neither touches the base's normal.
TEST_CASE("glTF clearcoatNormalTexture tilts the coat's highlight, not the base", "[pbr][gltf]") {
    TempDir dir("pbr-coat-normal");
    const auto quad_with_coat_map = [&](const std::string& name, const glm::vec3& texel) {
        Gltf g;
        const auto byte = [](float v) { return static_cast<uint8_t>(std::lround(v * 255.0f)); };
        std::vector<uint8_t> samples;
        for (int i = 0; i < 4; ++i)
            for (int a = 0; a < 3; ++a) samples.push_back(byte(texel[a]));
        g.doc["images"].push_back(
            {{"uri", "data:image/png;base64," + base64(png_of(2, 2, 3, samples))}});
        g.doc["textures"].push_back({{"source", 0}});
        json coat = {{"clearcoatFactor", 1}, {"clearcoatRoughnessFactor", 0.3}};
        if (texel.z > 0.0f) coat["clearcoatNormalTexture"] = {{"index", 0}};
        quad_with_materials(
            g, json::array({{{"pbrMetallicRoughness",
                              {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0}}},
                             {"extensions", {{"KHR_materials_clearcoat", coat}}}}}));
        g.write(dir.file(name));
        const std::string text =
            R"(output: { size: [64, 64], tonemap: none, passes: [color, normal] }
camera: { position: [0, 0, 4], target: [0, 0, 0], fov: 30 }
style: pbr
environment: none
lights: [{ type: directional, direction: [0, 0, -1], intensity: 1 }]
objects:
  - { name: quad, mesh: )" +
            name + " }\n";
        return render_yaml(dir.path(), text, 1, 2);
    };
    const float tilt = glm::radians(25.0f);
    const FrameImages smooth = quad_with_coat_map("smooth.gltf", glm::vec3(0.0f));
    const FrameImages flat = quad_with_coat_map("flat.gltf", {0.5f, 0.5f, 1.0f});
    const FrameImages tilted = quad_with_coat_map(
        "tilted.gltf", {0.5f + 0.5f * std::sin(tilt), 0.5f, 0.5f + 0.5f * std::cos(tilt)});
    const glm::vec3 middle(0.0f, 0.0f, 0.0f);
    const float highlight = pixel_at(smooth, smooth.color, middle).g;
    INFO("coat highlight " << highlight);
    CHECK(highlight > 0.5f);
    CHECK(pixel_at(flat, flat.color, middle).g == Approx(highlight).epsilon(0.03));
    CHECK(pixel_at(tilted, tilted.color, middle).g < 0.1f * highlight);
    // The base's normal (the normal pass) stays the mesh's.
    for (const FrameImages* images : {&flat, &tilted}) {
        const glm::vec3 n = images->surface.normal.at(32, 32);  // the middle
        CHECK(n.z == Approx(1.0f).margin(1e-3));
    }
}

TEST_CASE(
    "material extensions: those facet draws say nothing, one it does not warns naming what "
    "is lost",
    "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    Gltf g;
    quad_with_materials(g, json::array({json::object()}));
    // One facet does not read: the warning names it and what is lost.
    g.doc["extensionsUsed"].push_back("ADOBE_materials_thin_transparency");
    // The ones it draws (style pbr) say nothing.
    const std::vector<const char*> drawn = {
        "KHR_materials_ior",          "KHR_materials_specular",
        "KHR_materials_clearcoat",    "KHR_materials_sheen",
        "KHR_materials_iridescence",  "KHR_materials_anisotropy",
        "KHR_materials_transmission", "KHR_materials_volume",
        "KHR_materials_dispersion",   "KHR_materials_diffuse_transmission"};
    for (const char* extension : drawn) g.doc["extensionsUsed"].push_back(extension);
    const std::string path = g.write(dir.file("extensions.gltf"));
    const Mesh mesh = load_gltf(path);
    INFO(all_warnings(mesh));
    CHECK(mesh.warnings.size() == 1);
    CHECK(warns(mesh,
                "uses the glTF extension ADOBE_materials_thin_transparency, which facet ignores: "
                "what it adds is not drawn"));
    for (const char* extension : drawn) {
        INFO(extension);
        CHECK_FALSE(warns(mesh, extension));
    }
}

TEST_CASE("glTF material fields of the wrong JSON type are refused by their path", "[pbr][gltf]") {
    TempDir dir("pbr-gltf");
    struct Case {
        json material;
        std::string says;
    };
    const std::string ext = "materials[0].extensions.";
    const std::vector<Case> cases = {
        {{{"pbrMetallicRoughness", {{"metallicFactor", "1"}}}},
         "materials[0].pbrMetallicRoughness.metallicFactor must be a number"},
        {{{"pbrMetallicRoughness", {{"roughnessFactor", true}}}},
         "materials[0].pbrMetallicRoughness.roughnessFactor must be a number"},
        {{{"pbrMetallicRoughness", {{"metallicRoughnessTexture", 0}}}},
         "materials[0].pbrMetallicRoughness.metallicRoughnessTexture must be an object"},
        {{{"normalTexture", {{"index", 0}, {"scale", "2"}}}},
         "materials[0].normalTexture.scale must be a number"},
        {{{"occlusionTexture", {{"index", 0}, {"strength", nullptr}}}},
         "materials[0].occlusionTexture.strength must be a number"},
        {{{"occlusionTexture", {{"index", -1}}}},
         "materials[0].occlusionTexture.index must be an index"},
        {{{"extensions", {{"KHR_materials_ior", 1.5}}}},
         ext + "KHR_materials_ior must be an object"},
        {{{"extensions", {{"KHR_materials_ior", {{"ior", "1.5"}}}}}},
         ext + "KHR_materials_ior.ior must be a number"},
        {{{"extensions", {{"KHR_materials_specular", {{"specularFactor", "high"}}}}}},
         ext + "KHR_materials_specular.specularFactor must be a number"},
        {{{"extensions", {{"KHR_materials_specular", {{"specularColorFactor", {1, 1}}}}}}},
         ext + "KHR_materials_specular.specularColorFactor must be a list of 3 numbers"},
        {{{"extensions", {{"KHR_materials_specular", {{"specularColorFactor", {1, "1", 1}}}}}}},
         ext + "KHR_materials_specular.specularColorFactor must be a list of 3 numbers"},
        {{{"extensions", {{"KHR_materials_specular", {{"specularTexture", {{"texCoord", 0}}}}}}}},
         ext + "KHR_materials_specular.specularTexture.index must be present"},
        {{{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", json::array()}}}}}},
         ext + "KHR_materials_clearcoat.clearcoatFactor must be a number"},
        {{{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatRoughnessFactor", "smooth"}}}}}},
         ext + "KHR_materials_clearcoat.clearcoatRoughnessFactor must be a number"},
        {{{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatTexture", "coat.png"}}}}}},
         ext + "KHR_materials_clearcoat.clearcoatTexture must be an object"},
        {{{"extensions",
           {{"KHR_materials_clearcoat",
             {{"clearcoatNormalTexture", {{"index", 0}, {"scale", "1"}}}}}}}},
         ext + "KHR_materials_clearcoat.clearcoatNormalTexture.scale must be a number"},
    };
    for (const Case& c : cases) {
        INFO(c.says);
        Gltf g;
        mid_grey_textures(g, 1);
        quad_with_materials(g, json::array({c.material}));
        const std::string path = g.write(dir.file("wrong-type.gltf"));
        require_input_error([&] { load_gltf(path); }, path + ": " + c.says);
    }
}

// --- OBJ/MTL: the PBR extension ---------------------------------------------

namespace {

// A unit quad with texture coordinates drawn with material `material` of
// `mtl`, written into `dir`; returns that material as loaded.
Material obj_material(const TempDir& dir, const std::string& mtl, const std::string& material) {
    write_text(dir.file("m.mtl"), mtl);
    const std::string path = write_text(dir.file("m.obj"),
                                        "mtllib m.mtl\n"
                                        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                        "vn 0 0 1\n"
                                        "usemtl " +
                                            material + "\nf 1/1/1 2/2/1 3/3/1 4/4/1\n");
    const Mesh mesh = load_obj(path);
    INFO(all_warnings(mesh));
    REQUIRE(mesh.parts.size() == 1);
    return material_of(mesh, mesh.parts[0]);
}

// The roughness MTL's Phong exponent Ns stands for: GGX's alpha^2 =
// 2 / (Ns + 2), alpha = roughness^2 (docs/pbr.md, "From files").
float roughness_of_exponent(float ns) {
    return std::sqrt(std::sqrt(2.0f / (ns + 2.0f)));
}

// A grey PNG (one channel) of width x height, its bytes row by row.
void write_grey_png(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& bytes) {
    write_bytes(path, png_of(width, height, 1, bytes));
}

}  // namespace

TEST_CASE("MTL Pr and Pm give roughness and metalness", "[pbr][obj]") {
    TempDir dir("pbr-obj");
    const Material m =
        obj_material(dir, "newmtl brushed\nKd 1 1 1\nNs 10\nPr 0.35\nPm 0.8\n", "brushed");
    CHECK(m.roughness == Approx(0.35f));
    CHECK(m.metallic == Approx(0.8f));
    CHECK_FALSE(m.metal_rough_map);
}

TEST_CASE("MTL without Pr takes its roughness from Ns, and is a dielectric without Pm",
          "[pbr][obj]") {
    TempDir dir("pbr-obj");
    SECTION("neither Pr nor Pm") {
        const Material m = obj_material(dir, "newmtl phong\nKd 1 1 1\nNs 98\n", "phong");
        CHECK(m.roughness == Approx(roughness_of_exponent(98.0f)));
        CHECK(m.metallic == 0.0f);
    }
    SECTION("Pm alone: the roughness still follows Ns") {
        const Material m = obj_material(dir, "newmtl metal\nKd 1 1 1\nNs 198\nPm 1\n", "metal");
        CHECK(m.roughness == Approx(roughness_of_exponent(198.0f)));
        CHECK(m.metallic == 1.0f);
    }
    SECTION("Pr 0 given is a mirror, not the Ns roughness") {
        const Material m = obj_material(dir, "newmtl mirror\nKd 1 1 1\nNs 10\nPr 0\n", "mirror");
        CHECK(m.roughness == 0.0f);
        CHECK(m.metallic == 0.0f);
    }
    SECTION("another material's Pr does not count") {
        const Material m = obj_material(
            dir, "newmtl given\nPr 0.1\nPm 1\n\nnewmtl phong\nKd 1 1 1\nNs 18\n", "phong");
        CHECK(m.roughness == Approx(roughness_of_exponent(18.0f)));
        CHECK(m.metallic == 0.0f);
    }
}

TEST_CASE("MTL map_Pr and map_Pm become one data map: G roughness, B metalness", "[pbr][obj]") {
    TempDir dir("pbr-obj");
    const std::vector<uint8_t> rough = {0, 85, 170, 255};
    const std::vector<uint8_t> metal = {255, 0, 128, 64};
    write_grey_png(dir.file("rough.png"), 2, 2, rough);
    write_grey_png(dir.file("metal.png"), 2, 2, metal);
    const Material m = obj_material(
        dir, "newmtl mapped\nKd 1 1 1\nPr 0.5\nPm 1\nmap_Pr rough.png\nmap_Pm metal.png\n",
        "mapped");
    // The maps multiply the values given.
    CHECK(m.roughness == Approx(0.5f));
    CHECK(m.metallic == 1.0f);
    REQUIRE(m.metal_rough_map);
    const Texture& map = *m.metal_rough_map.texture;
    CHECK(map.format() == Texture::Format::data8);
    REQUIRE(map.width == 2);
    REQUIRE(map.height == 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            INFO("texel " << x << ", " << y);
            const size_t i = static_cast<size_t>(y * 2 + x);
            const glm::vec4 t = map.texel(0, x, y);
            CHECK(t.g == Approx(as_number(rough[i])).margin(1e-6));
            CHECK(t.b == Approx(as_number(metal[i])).margin(1e-6));
        }
}

TEST_CASE("MTL roughness and metal maps of different sizes combine at the larger size",
          "[pbr][obj]") {
    TempDir dir("pbr-obj");
    // A 4 x 1 ramp and a 2 x 1 map, dark left, bright right.
    const std::vector<uint8_t> ramp = {10, 90, 170, 250};
    const uint8_t dark = 0, bright = 200;
    write_grey_png(dir.file("ramp.png"), 4, 1, ramp);
    write_grey_png(dir.file("two_tone.png"), 2, 1, {dark, bright});
    SECTION("the roughness map larger") {
        const Material m =
            obj_material(dir, "newmtl mapped\nmap_Pr ramp.png\nmap_Pm two_tone.png\n", "mapped");
        REQUIRE(m.metal_rough_map);
        const Texture& map = *m.metal_rough_map.texture;
        REQUIRE(map.width == 4);
        REQUIRE(map.height == 1);
        for (int x = 0; x < 4; ++x)
            CHECK(map.texel(0, x, 0).g == Approx(as_number(ramp[size_t(x)])).margin(1e-6));
        // The inner texels' centres, u = 3/8 and 5/8, lie a quarter and
        // three quarters of the way between the metal map's two centres.
        const float low = as_number(dark), high = as_number(bright);
        CHECK(map.texel(0, 1, 0).b == Approx(0.75f * low + 0.25f * high).margin(0.5 / 255));
        CHECK(map.texel(0, 2, 0).b == Approx(0.25f * low + 0.75f * high).margin(0.5 / 255));
    }
    SECTION("the metal map larger") {
        // Swapped: a 2-texel roughness map must not shrink the 4-texel metal map.
        const Material m =
            obj_material(dir, "newmtl mapped\nmap_Pr two_tone.png\nmap_Pm ramp.png\n", "mapped");
        REQUIRE(m.metal_rough_map);
        const Texture& map = *m.metal_rough_map.texture;
        REQUIRE(map.width == 4);
        for (int x = 0; x < 4; ++x)
            CHECK(map.texel(0, x, 0).b == Approx(as_number(ramp[size_t(x)])).margin(1e-6));
    }
}

TEST_CASE("MTL map_Pr or map_Pm alone is the value itself", "[pbr][obj]") {
    TempDir dir("pbr-obj");
    write_grey_png(dir.file("rough.png"), 2, 1, {64, 192});
    write_grey_png(dir.file("metal.png"), 2, 1, {0, 255});
    SECTION("map_Pr without Pr: roughness factor 1, not the mirror of an absent Pr") {
        const Material m = obj_material(dir, "newmtl r\nNs 10\nmap_Pr rough.png\n", "r");
        CHECK(m.roughness == 1.0f);
        CHECK(m.metallic == 0.0f);
        REQUIRE(m.metal_rough_map);
        CHECK(m.metal_rough_map.texture->texel(0, 1, 0).g == Approx(as_number(192)).margin(1e-6));
        // No metal map: B leaves the metalness as given.
        CHECK(m.metal_rough_map.texture->texel(0, 1, 0).b == 1.0f);
    }
    SECTION("map_Pm without Pm: metalness factor 1, roughness from Ns") {
        const Material m = obj_material(dir, "newmtl p\nNs 48\nmap_Pm metal.png\n", "p");
        CHECK(m.metallic == 1.0f);
        CHECK(m.roughness == Approx(roughness_of_exponent(48.0f)));
        REQUIRE(m.metal_rough_map);
        CHECK(m.metal_rough_map.texture->texel(0, 0, 0).b == 0.0f);
        CHECK(m.metal_rough_map.texture->texel(0, 0, 0).g == 1.0f);
    }
}

TEST_CASE("MTL norm is a normal map read as data", "[pbr][obj]") {
    TempDir dir("pbr-obj");
    write_bytes(dir.file("maps/bump.png"), flat_png(kMidByte));
    // The same file as the colour map too: each slot reads it its own way.
    const Material m = obj_material(
        dir, "newmtl bumpy\nKd 1 1 1\nmap_Kd maps/bump.png\nnorm maps/bump.png\n", "bumpy");
    require_read_as_data(m.normal_map);
    require_read_as_colour(m.base_color_map);
}

TEST_CASE("MTL terms facet does not draw are named in one warning per material", "[pbr][obj]") {
    TempDir dir("pbr-obj-lost");
    write_bytes(dir.file("h.png"), flat_png(kMidByte));
    write_text(dir.file("m.mtl"),
               "newmtl lamp\nKd 1 1 1\nKe 1 0.5 0\nd 0.5\nmap_Bump h.png\nmap_Ks h.png\n"
               "newmtl plain\nKd 0.5 0.5 0.5\nKe 0 0 0\n");
    const std::string path = write_text(dir.file("m.obj"),
                                        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                        "usemtl lamp\nf 1 2 3\nusemtl plain\nf 1 2 3\n");
    const Mesh mesh = load_obj(path);
    const std::string all = all_warnings(mesh);
    INFO(all);
    CHECK_THAT(all, Contains("material 'lamp': bump (a height map; `norm` is read), map_Ks, "
                             "Ke (emission), d (transparency) not drawn"));
    CHECK_THAT(all, !Contains("material 'plain'"));
}
