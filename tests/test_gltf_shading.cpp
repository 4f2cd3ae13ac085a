// glTF 2.0 loading (src/assets/gltf_loader.cpp), what shading reads: normals
// made up where the file has none or bad ones, materials, and base colour
// textures with their samplers. The files are tiny ones with known answers,
// built here.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "core/image.hpp"

using namespace facet::test;
using nlohmann::json;

TEST_CASE("glTF without normals gets flat normals perpendicular to faces", "[assets][gltf]") {
    // Two triangles sharing the edge (0,0,0)-(1,0,0), folded by about 11 degrees:
    // flat shading must not average them even at that small angle.
    TempDir dir("gltf");
    Gltf g;
    int pos = g.floats({0, 0, 0, 1, 0, 0, 0.5f, 1, 0.1f, 0.5f, -1, 0.1f}, "VEC3");
    int idx = g.indices(std::vector<uint16_t>{0, 1, 2, 1, 0, 3}, kUShort);
    g.one_node_scene({{"attributes", {{"POSITION", pos}}}, {"indices", idx}});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("flat.gltf")));
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 2);
    CHECK(mesh.vertex_count() == 6);  // the shared edge is split
    const glm::vec3 want[2] = {glm::normalize(glm::vec3(0, -0.1f, 1)),
                               glm::normalize(glm::vec3(0, 0.1f, 1))};
    const auto& part = mesh.parts[0];
    for (size_t t = 0; t < 2; ++t) {
        glm::vec3 f = glm::normalize(face_cross(part, t));
        require_vec3(f, want[t], 1e-5f);
        for (int k = 0; k < 3; ++k) {
            glm::vec3 n = part.normals[part.indices[3 * t + k]];
            require_vec3(n, f, 1e-5f);
            // perpendicular to both edges of the face
            CHECK(glm::dot(n, corner(part, t, 1) - corner(part, t, 0)) ==
                  Approx(0.0f).margin(1e-5));
            CHECK(glm::dot(n, corner(part, t, 2) - corner(part, t, 0)) ==
                  Approx(0.0f).margin(1e-5));
        }
    }
}

TEST_CASE("glTF zero-length normals are replaced by face normals", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    int nrm = g.floats({0, 0, 0, 0, 0, 1, 0, 0, 1}, "VEC3");
    g.one_node_scene(
        {{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}, {"NORMAL", nrm}}}});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("zeronormal.gltf")));
    check_sane(mesh);
    for (const auto& n : mesh.parts[0].normals) require_vec3(n, {0, 0, 1});
}

TEST_CASE("glTF materials: baseColorFactor, double sided, default", "[assets][gltf]") {
    TempDir dir("gltf");
    Gltf g;
    g.doc["materials"] =
        json::array({{{"name", "paint"},
                      {"doubleSided", true},
                      {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}}}}});
    int pos = g.floats(kTriangle, "VEC3");
    int with = g.mesh({{"attributes", {{"POSITION", pos}}}, {"material", 0}});
    int without = g.mesh({{"attributes", {{"POSITION", pos}}}});
    g.scene({g.node({{"mesh", with}}), g.node({{"mesh", without}, {"translation", {0, 0, 1}}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("materials.gltf")));
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 2);
    const auto& paint = material_of(mesh, mesh.parts[0]);
    CHECK(paint.name == "paint");
    CHECK(paint.color.r == Approx(0.2f));
    CHECK(paint.color.g == Approx(0.4f));
    CHECK(paint.color.b == Approx(0.6f));
    CHECK(paint.double_sided);
    CHECK(paint.base_color_map.texture == nullptr);
    const auto& fallback = material_of(mesh, mesh.parts[1]);
    CHECK(fallback.name != "paint");
    CHECK(fallback.color == glm::vec3(1));  // glTF's default base colour is white
    CHECK_FALSE(fallback.double_sided);
}

TEST_CASE("glTF base colour texture from a data URI, with sampler wrap", "[assets][gltf]") {
    TempDir dir("gltf");
    facet::ColorImage img(3, 2, {0, 0, 0, 1});
    img.at(2, 0) = {1, 1, 1, 1};  // top-right white
    img.at(0, 1) = {1, 0, 0, 1};  // bottom-left red
    Gltf g;
    g.doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(png_bytes(img))}}});
    g.doc["samplers"] = json::array({{{"wrapS", 33071}, {"wrapT", 33071}}, json::object()});
    g.doc["textures"] =
        json::array({{{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}}});
    json tex0 = {{"index", 0}};
    json tex1 = {{"index", 1}, {"texCoord", 1}};
    json mat0 = {{"pbrMetallicRoughness", {{"baseColorTexture", tex0}}}};
    json mat1 = {{"pbrMetallicRoughness", {{"baseColorTexture", tex1}}}};
    g.doc["materials"] = json::array({mat0, mat1});
    int pos = g.floats(kTriangle, "VEC3");
    int uv0 = g.floats({0, 0, 1, 0, 0, 1}, "VEC2");
    int uv1 = g.floats({0.5f, 0.5f, 0.25f, 0.25f, 0.75f, 0.75f}, "VEC2");
    const json attributes = {{"POSITION", pos}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}};
    int a = g.mesh({{"attributes", attributes}, {"material", 0}});
    int b = g.mesh({{"attributes", attributes}, {"material", 1}});
    g.scene({g.node({{"mesh", a}}), g.node({{"mesh", b}})});
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("textured.gltf")));
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 2);
    const auto& ma = material_of(mesh, mesh.parts[0]);
    const auto& mb = material_of(mesh, mesh.parts[1]);
    REQUIRE(ma.base_color_map.texture != nullptr);
    REQUIRE(mb.base_color_map.texture != nullptr);
    CHECK(ma.base_color_map.texture->width == 3);
    CHECK(ma.base_color_map.texture->height == 2);
    CHECK(ma.base_color_map.texture->texel(0, 2, 0) == glm::vec4(1, 1, 1, 1));
    CHECK(ma.base_color_map.texture->texel(0, 0, 1) == glm::vec4(1, 0, 0, 1));
    CHECK(ma.base_color_map.texture->sampler.wrap_s == facet::Wrap::clamp);
    CHECK(mb.base_color_map.texture->sampler.wrap_s == facet::Wrap::repeat);  // the glTF default
    // Material 0 reads TEXCOORD_0; material 1 asks for TEXCOORD_1. No v flip in glTF.
    CHECK(ma.base_color_map.uv_set == 0);
    CHECK(mb.base_color_map.uv_set == 1);
    CHECK(mesh.parts[0].uvs[1] == glm::vec2(1, 0));
    CHECK(mesh.parts[1].uvs1[1] == glm::vec2(0.25f, 0.25f));
}
