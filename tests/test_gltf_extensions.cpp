// glTF extensions: the ones facet reads (KHR_texture_transform,
// KHR_mesh_quantization), and what happens with the others: an error naming
// the extension when the file requires it, a warning when it only uses it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

// A quad (two triangles) with two UV sets and a material whose base colour
// texture carries `texture_info` (index, texCoord, extensions).
std::string textured_quad(const TempDir& dir, const json& texture_info) {
    Gltf g;
    const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const std::vector<float> uv0 = {0, 0, 1, 0, 1, 1, 0, 1};
    const std::vector<float> uv1 = {0.25f, 0.25f, 0.5f, 0.25f, 0.5f, 0.5f, 0.25f, 0.5f};
    const std::vector<uint16_t> indices = {0, 1, 2, 0, 2, 3};
    json info = texture_info;
    info["index"] = 0;
    facet::ColorImage texel(2, 2);  // any image: only the UVs are looked at
    g.doc["images"] = {{{"uri", "data:image/png;base64," + base64(png_bytes(texel))}}};
    g.doc["textures"] = {{{"source", 0}}};
    g.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", info}}}}};
    g.one_node_scene({{"attributes",
                       {{"POSITION", g.floats(positions, "VEC3")},
                        {"TEXCOORD_0", g.floats(uv0, "VEC2")},
                        {"TEXCOORD_1", g.floats(uv1, "VEC2")}}},
                      {"indices", g.indices(indices, kUShort)},
                      {"material", 0}});
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    return g.write(dir.file("quad.gltf"));
}

// The UV the base colour texture reads at the vertex at `position`: the
// slot's coordinate set, mapped by its transform.
glm::vec2 uv_at(const facet::Mesh& mesh, glm::vec3 position) {
    const auto& part = mesh.parts.at(0);
    const facet::TextureSlot& slot = mesh.materials.at(part.material).base_color_map;
    const auto& set = slot.uv_set == 1 ? part.uvs1 : part.uvs;
    REQUIRE(set.size() == part.positions.size());
    for (size_t i = 0; i < part.positions.size(); ++i)
        if (part.positions[i] == position) return slot.map(set[i]);
    FAIL("no vertex there");
    return {};
}

}  // namespace

TEST_CASE("KHR_texture_transform moves, turns and scales the UVs it applies to",
          "[gltf][extensions]") {
    TempDir dir("gltf-ext");
    // Worked by hand from the extension's matrix T·R·S with rotation
    // π/2, scale (2, 1), offset (0.5, 0):
    //   u' = 0.5 + cos·2u + sin·v = 0.5 + v
    //   v' = 0   - sin·2u + cos·v = -2u
    const facet::Mesh turned = facet::load_gltf(textured_quad(
        dir, {{"extensions",
               {{"KHR_texture_transform",
                 {{"offset", {0.5, 0}}, {"rotation", M_PI / 2}, {"scale", {2, 1}}}}}}}));
    const glm::vec2 corner = uv_at(turned, {1, 0, 0});  // file UV (1, 0)
    CHECK(corner.x == Approx(0.5).margin(1e-6));
    CHECK(corner.y == Approx(-2).margin(1e-6));
    const glm::vec2 top = uv_at(turned, {0, 1, 0});  // file UV (0, 1)
    CHECK(top.x == Approx(1.5).margin(1e-6));
    CHECK(top.y == Approx(0).margin(1e-6));

    // Scale alone: a texture repeated twice, as Blender writes for a
    // Mapping node scaled by 2.
    const facet::Mesh scaled = facet::load_gltf(
        textured_quad(dir, {{"extensions", {{"KHR_texture_transform", {{"scale", {2, 2}}}}}}}));
    CHECK(uv_at(scaled, {1, 1, 0}) == glm::vec2(2, 2));

    // texCoord in the extension picks the second UV set over the textureInfo's.
    const facet::Mesh second = facet::load_gltf(textured_quad(
        dir, {{"texCoord", 0},
              {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}, {"offset", {1, 0}}}}}}}));
    CHECK(uv_at(second, {1, 1, 0}) == glm::vec2(1.5f, 0.5f));
    // And without the extension, textureInfo.texCoord picks it.
    const facet::Mesh plain = facet::load_gltf(textured_quad(dir, {{"texCoord", 1}}));
    CHECK(uv_at(plain, {1, 0, 0}) == glm::vec2(0.5f, 0.25f));
    CHECK(turned.warnings.empty());

    require_input_error(
        [&] {
            facet::load_gltf(textured_quad(
                dir, {{"extensions", {{"KHR_texture_transform", {{"scale", {2}}}}}}}));
        },
        "KHR_texture_transform scale must be an array of 2 numbers");
}

TEST_CASE("a required glTF extension facet lacks is an error that names it, a used one warns",
          "[gltf][extensions]") {
    TempDir dir("gltf-ext");
    Gltf g;
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    g.doc["extensionsUsed"] = {"KHR_animation_pointer", "KHR_texture_basisu",
                               "KHR_lights_punctual"};
    const facet::Mesh mesh = facet::load_gltf(g.write(dir.file("used.gltf")));
    // The lights are read; KHR_texture_basisu loses nothing where no
    // texture has a KTX2 image (tests/test_gltf_images.cpp has those).
    REQUIRE(mesh.warnings.size() == 1);
    CHECK_THAT(mesh.warnings[0].describe(),
               Contains("uses the glTF extension KHR_animation_pointer, which facet ignores: "
                        "its animations of materials, lights and cameras do not play"));

    g.doc["extensionsRequired"] = {"KHR_animation_pointer"};
    const std::string required = g.write(dir.file("required.gltf"));
    require_input_error([&] { facet::load_gltf(required); },
                        "required.gltf: requires the glTF extension KHR_animation_pointer, which "
                        "facet does not support");

    // KHR_mesh_quantization and KHR_texture_transform are read: no error.
    g.doc["extensionsRequired"] = {"KHR_mesh_quantization", "KHR_texture_transform"};
    g.doc["extensionsUsed"] = {"KHR_mesh_quantization", "KHR_texture_transform"};
    CHECK(facet::load_gltf(g.write(dir.file("read.gltf"))).warnings.empty());
}

TEST_CASE("a .glb that needs an unsupported extension names it, not a buffer error",
          "[gltf][extensions]") {
    // A second buffer with a length but no data, as compressed files have:
    // tinygltf alone stops at it ("Invalid byteLength") before any check of
    // the extensions.
    TempDir dir("gltf-ext");
    Gltf g;
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    g.doc["extensionsUsed"] = {"KHR_animation_pointer"};
    g.doc["extensionsRequired"] = {"KHR_animation_pointer"};
    json doc = g.doc;
    doc["buffers"] = {{{"byteLength", g.bin.size()}}, {{"byteLength", 4096}}};
    doc["bufferViews"][0]["buffer"] = 1;
    std::string text = doc.dump();
    while (text.size() % 4) text += ' ';
    std::vector<uint8_t> bin(g.bin.begin(), g.bin.end());
    while (bin.size() % 4) bin.push_back(0);
    std::vector<uint8_t> glb;
    auto u32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) glb.push_back(static_cast<uint8_t>(v >> (8 * i)));
    };
    glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    u32(static_cast<uint32_t>(text.size()));
    glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
    glb.insert(glb.end(), text.begin(), text.end());
    u32(static_cast<uint32_t>(bin.size()));
    glb.insert(glb.end(), {'B', 'I', 'N', 0});
    glb.insert(glb.end(), bin.begin(), bin.end());
    const std::string path = write_bytes(dir.file("packed.glb"), glb);
    require_input_error([&] { facet::load_gltf(path); },
                        "packed.glb: requires the glTF extension KHR_animation_pointer");
}
