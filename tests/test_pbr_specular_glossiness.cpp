// KHR_materials_pbrSpecularGlossiness (archived), read as the dielectric it
// describes (docs/pbr.md, "From files"): a file that requires it renders,
// its factors and maps are read with their meanings, a material equals its
// metallic-roughness equivalent where one exists, and its map applies the
// same values texel by texel as its factors do. Every file is made here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "assets/texture.hpp"
#include "core/half.hpp"
#include "render_check.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

const char* const kExtension = "KHR_materials_pbrSpecularGlossiness";

// A quad whose material 0 is `material`, with textures 0 and 1 the PNGs
// given (data URIs), written to `dir`/`name`.
std::string quad_file(const TempDir& dir, const json& material, const std::string& name,
                      const std::vector<std::vector<uint8_t>>& pngs = {}) {
    Gltf g;
    for (size_t i = 0; i < pngs.size(); ++i) {
        g.doc["images"].push_back({{"uri", "data:image/png;base64," + base64(pngs[i])}});
        g.doc["textures"].push_back({{"source", i}});
    }
    g.doc["materials"] = json::array({material});
    g.one_quad_scene();
    if (material.contains("extensions") && material["extensions"].contains(kExtension)) {
        g.doc["extensionsUsed"] = {kExtension};
        g.doc["extensionsRequired"] = {kExtension};
    }
    return g.write(dir.file(name));
}

// The quad seen at a slant under a light and the studio, colour pass, linear.
FrameImages render_quad(const TempDir& dir, const std::string& file) {
    const std::string text =
        "output: { size: [48, 48], tonemap: none }\n"
        "style: pbr\nenvironment: studio\n"
        "camera: { position: [0.4, 1.3, 2.2], target: [0, 0, 0], fov: 50 }\n"
        "lights: [{ type: directional, direction: [-0.3, -0.4, -1], intensity: 2 }]\n"
        "objects:\n  - name: quad\n    mesh: " +
        file + "\n";
    return render_yaml(dir.path(), text);
}

// The largest difference of any channel of any pixel the quad covers in both.
float largest_difference(const FrameImages& a, const FrameImages& b) {
    float largest = 0.0f;
    for (int y = 0; y < a.color.height; ++y)
        for (int x = 0; x < a.color.width; ++x) {
            const glm::vec4 p = to_float(a.color.at(x, y)), q = to_float(b.color.at(x, y));
            for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(p[c] - q[c]));
        }
    return largest;
}

// The mean of the colour pass's red, to check a render shows something.
float mean_red(const FrameImages& images) {
    double sum = 0.0;
    for (int y = 0; y < images.color.height; ++y)
        for (int x = 0; x < images.color.width; ++x) sum += to_float(images.color.at(x, y)).r;
    return static_cast<float>(sum / (images.color.width * images.color.height));
}

json spec_gloss(const json& fields) {
    return {{"extensions", {{kExtension, fields}}}};
}

}  // namespace

TEST_CASE("specular-glossiness: the factors are read as the dielectric they describe",
          "[pbr][gltf]") {
    TempDir dir("spec-gloss");
    const Mesh mesh = load_gltf(quad_file(dir,
                                          spec_gloss({{"diffuseFactor", {0.5, 0.4, 0.3, 0.75}},
                                                      {"specularFactor", {0.2, 0.1, 0.05}},
                                                      {"glossinessFactor", 0.7}}),
                                          "factors.gltf"));
    CHECK(mesh.warnings.empty());
    const Material& m = mesh.materials[0];
    // c (1 - max(s)), f0 = s (0.04 * specular_color), roughness 1 - g.
    CHECK(m.color.r == Approx(0.5f * 0.8f));
    CHECK(m.color.b == Approx(0.3f * 0.8f));
    CHECK(m.alpha == Approx(0.75f));
    CHECK(m.metallic == 0.0f);
    CHECK(m.roughness == Approx(0.3f));
    CHECK(0.04f * m.specular_color.r == Approx(0.2f));
    CHECK(0.04f * m.specular_color.b == Approx(0.05f));
    CHECK(m.specular_weight == 1.0f);
    CHECK_FALSE(m.specular_glossiness_map);
    // Absent factors: white diffuse, white specular, glossiness 1.
    const Mesh bare = load_gltf(quad_file(dir, spec_gloss(json::object()), "bare.gltf"));
    CHECK(bare.materials[0].color == glm::vec3(0.0f));  // 1 - max(1, 1, 1)
    CHECK(bare.materials[0].roughness == 0.0f);
}

TEST_CASE("specular-glossiness: the diffuse map is colour, the specular-glossiness map too",
          "[pbr][gltf]") {
    TempDir dir("spec-gloss");
    const Mesh mesh = load_gltf(quad_file(
        dir,
        spec_gloss({{"diffuseTexture", {{"index", 0}}},
                    {"specularGlossinessTexture", {{"index", 1}}},
                    {"specularFactor", {0.5, 0.5, 0.5}},
                    {"glossinessFactor", 0.8}}),
        "maps.gltf", {flat_png(kMidByte), png_of(2, 2, 4, std::vector<uint8_t>(16, kMidByte))}));
    const Material& m = mesh.materials[0];
    REQUIRE(m.base_color_map.texture);
    CHECK(m.base_color_map.texture->format() == Texture::Format::srgb8);
    REQUIRE(m.specular_glossiness_map.texture);
    CHECK(m.specular_glossiness_map.texture->format() == Texture::Format::srgb8);
    // With the map, the factors wait for each texel: the diffuse is not yet scaled.
    CHECK(m.color == glm::vec3(1.0f));
    CHECK(m.specular_factor == glm::vec3(0.5f));
    CHECK(m.glossiness_factor == Approx(0.8f));
    CHECK((m.features() & kPhysicalMaps) != 0);
}

TEST_CASE("specular-glossiness: bad factors are refused by their path", "[pbr][gltf]") {
    TempDir dir("spec-gloss");
    struct Bad {
        json fields;
        std::string says;
    };
    const std::string at = "materials[0].extensions.KHR_materials_pbrSpecularGlossiness.";
    for (const Bad& bad :
         {Bad{{{"glossinessFactor", 2}}, "glossinessFactor must be from 0 to 1"},
          Bad{{{"diffuseFactor", {1, 1, 1}}}, at + "diffuseFactor must be a list of 4 numbers"},
          Bad{{{"specularFactor", {0.5, 2, 0}}}, "specularFactor must hold numbers from 0 to 1"},
          Bad{{{"diffuseFactor", {0.5, 0.5, 0.5, -1}}},
              "diffuseFactor must hold numbers from 0 to 1"}}) {
        INFO(bad.says);
        const std::string path = quad_file(dir, spec_gloss(bad.fields), "bad.gltf");
        require_input_error([&] { load_gltf(path); }, bad.says);
    }
}

TEST_CASE("specular-glossiness: a material renders as its metallic-roughness equivalent",
          "[render][pbr][gltf]") {
    TempDir dir("spec-gloss");
    struct Pair {
        const char* name;
        json spec_gloss, metal_rough;
    };
    // A dielectric: c_diff = c (1 - 0.04), f0 0.04, roughness 1 - g. A metal:
    // no diffuse, f0 its colour (the metal's F0 is its base colour).
    const std::vector<Pair> pairs = {
        {"dielectric",
         spec_gloss({{"diffuseFactor", {0.6, 0.3, 0.2, 1}},
                     {"specularFactor", {0.04, 0.04, 0.04}},
                     {"glossinessFactor", 0.6}}),
         {{"pbrMetallicRoughness",
           {{"baseColorFactor", {0.6 * 0.96, 0.3 * 0.96, 0.2 * 0.96, 1}},
            {"metallicFactor", 0},
            {"roughnessFactor", 0.4}}}}},
        {"metal",
         spec_gloss({{"diffuseFactor", {0, 0, 0, 1}},
                     {"specularFactor", {0.95, 0.64, 0.54}},
                     {"glossinessFactor", 0.7}}),
         {{"pbrMetallicRoughness",
           {{"baseColorFactor", {0.95, 0.64, 0.54, 1}},
            {"metallicFactor", 1},
            {"roughnessFactor", 0.3}}}}},
    };
    for (const Pair& pair : pairs) {
        INFO(pair.name);
        const FrameImages sg = render_quad(dir, quad_file(dir, pair.spec_gloss, "sg.gltf"));
        const FrameImages mr = render_quad(dir, quad_file(dir, pair.metal_rough, "mr.gltf"));
        CHECK(mean_red(sg) > 0.05f);
        CHECK(largest_difference(sg, mr) <= 1.0f / 255.0f);
    }
}

TEST_CASE("specular-glossiness: its map gives, texel by texel, what the same factors give",
          "[render][pbr][gltf]") {
    TempDir dir("spec-gloss");
    // The map holds specular (sRGB bytes) and glossiness (A, a number); the
    // factors scale them. The same values given as factors alone must render
    // the same, within the rounding of the bytes.
    const uint8_t rgb[3] = {200, 150, 90}, gloss_byte = 160;
    std::vector<uint8_t> texels;
    for (int i = 0; i < 4; ++i) {
        for (uint8_t c : rgb) texels.push_back(c);
        texels.push_back(gloss_byte);
    }
    const auto srgb = [](uint8_t byte) {
        const double v = byte / 255.0;
        return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    const double factor = 0.3, glossiness = 0.9;
    const json diffuse = {0.7, 0.5, 0.3, 1};
    const FrameImages mapped =
        render_quad(dir, quad_file(dir,
                                   spec_gloss({{"diffuseFactor", diffuse},
                                               {"specularFactor", {factor, factor, factor}},
                                               {"glossinessFactor", glossiness},
                                               {"specularGlossinessTexture", {{"index", 0}}}}),
                                   "mapped.gltf", {png_of(2, 2, 4, texels)}));
    const FrameImages factors = render_quad(
        dir, quad_file(dir,
                       spec_gloss(
                           {{"diffuseFactor", diffuse},
                            {"specularFactor",
                             {factor * srgb(rgb[0]), factor * srgb(rgb[1]), factor * srgb(rgb[2])}},
                            {"glossinessFactor", glossiness * gloss_byte / 255.0}}),
                       "factors.gltf"));
    CHECK(mean_red(mapped) > 0.05f);
    CHECK(largest_difference(mapped, factors) <= 1.0f / 255.0f);
}
