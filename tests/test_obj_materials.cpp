// Wavefront OBJ loading (src/assets/obj_loader.cpp), materials: .mtl
// libraries, colours, texture maps and the odd ways files name them. The
// files are small ones with known answers, written here.
#include <catch2/catch.hpp>

#include <map>
#include <string>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "asset_support.hpp"
#include "assets/mesh.hpp"
#include "core/image.hpp"

using namespace facet::test;

namespace {

// 2x2 texture: red, green / blue, white, all exactly representable in sRGB bytes.
facet::ColorImage checker_image() {
    facet::ColorImage img(2, 2);
    img.at(0, 0) = {1, 0, 0, 1};
    img.at(1, 0) = {0, 1, 0, 1};
    img.at(0, 1) = {0, 0, 1, 1};
    img.at(1, 1) = {1, 1, 1, 1};
    return img;
}

}  // namespace

TEST_CASE("OBJ materials: Kd colour, shininess and map_Kd texture", "[assets][obj]") {
    TempDir dir("obj");
    write_png(dir.file("textures/checker.png"), checker_image());
    write_text(dir.file("scene.mtl"),
               "# two materials\n"
               "newmtl red\nKd 0.8 0.1 0.2\nKs 0.5 0.5 0.5\nNs 64\n\n"
               "newmtl textured\nKd 0 0 0\nmap_Kd textures/checker.png\n");
    std::string path = write_text(dir.file("scene.obj"),
                                  "mtllib scene.mtl\n"
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                  "vt 0 0\nvt 1 0\nvt 1 1\n"
                                  "usemtl red\nf 1 2 3 4\n"
                                  "usemtl textured\nf 1/1 2/2 5/3\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 2);
    std::map<std::string, const facet::MeshPart*> by_name;
    for (const auto& part : mesh.parts) by_name[material_of(mesh, part).name] = &part;
    REQUIRE(by_name.count("red"));
    REQUIRE(by_name.count("textured"));
    CHECK(by_name["red"]->triangle_count() == 2);
    CHECK(by_name["textured"]->triangle_count() == 1);

    const auto& red = material_of(mesh, *by_name["red"]);
    CHECK(red.color.r == Approx(0.8f));
    CHECK(red.color.g == Approx(0.1f));
    CHECK(red.color.b == Approx(0.2f));
    CHECK(red.shininess == Approx(64.0f));
    CHECK(red.specular == Approx(0.5f));
    CHECK(red.base_color_map.texture == nullptr);

    const auto& textured = material_of(mesh, *by_name["textured"]);
    REQUIRE(textured.base_color_map.texture != nullptr);
    CHECK(textured.base_color_map.texture->width == 2);
    CHECK(textured.base_color_map.texture->height == 2);
    const facet::Texture& t = *textured.base_color_map.texture;
    REQUIRE(t.width == 2);
    REQUIRE(t.height == 2);
    CHECK(t.texel(0, 0, 0) == glm::vec4(1, 0, 0, 1));  // top-left red
    CHECK(t.texel(0, 1, 0) == glm::vec4(0, 1, 0, 1));
    CHECK(t.texel(0, 0, 1) == glm::vec4(0, 0, 1, 1));
    CHECK(t.texel(0, 1, 1) == glm::vec4(1, 1, 1, 1));
    // Kd 0 0 0 next to a map means "use the map": the texture must not be blacked out.
    CHECK(textured.color == glm::vec3(1));
}

TEST_CASE("OBJ map_Kd written with Windows backslashes is found", "[assets][obj]") {
    TempDir dir("obj");
    write_png(dir.file("maps/checker.png"), checker_image());
    write_text(dir.file("win.mtl"), "newmtl m\r\nKd 1 1 1\r\nmap_Kd .\\maps\\checker.png\r\n");
    std::string path = write_text(dir.file("win.obj"),
                                  "mtllib win.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvt 0 0\r\n"
                                  "usemtl m\r\nf 1/1 2/1 3/1\r\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    REQUIRE(mesh.parts.size() == 1);
    const auto& mat = material_of(mesh, mesh.parts[0]);
    CHECK(mat.name == "m");
    REQUIRE(mat.base_color_map.texture != nullptr);
    CHECK(mat.base_color_map.texture->width == 2);
}

TEST_CASE("OBJ faces without a known material use a default material", "[assets][obj]") {
    TempDir dir("obj");
    write_text(dir.file("one.mtl"), "newmtl known\nKd 0 0 1\n");
    std::string path = write_text(dir.file("mixed.obj"),
                                  "mtllib one.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "f 1 2 3\nusemtl known\nf 1 2 3\nusemtl unknown\nf 3 2 1\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 3);
    size_t known = 0, other = 0;
    for (const auto& part : mesh.parts) {
        if (material_of(mesh, part).name == "known") {
            known += part.triangle_count();
            CHECK(material_of(mesh, part).color == glm::vec3(0, 0, 1));
        } else {
            other += part.triangle_count();
        }
    }
    CHECK(known == 1);
    CHECK(other == 2);
}

TEST_CASE("OBJ with a missing .mtl still loads its geometry", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(
        dir.file("nomtl.obj"), "mtllib absent.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
    facet::Mesh mesh = facet::load_obj(path);
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 1);
}

TEST_CASE("OBJ map_Kd naming a missing image is an error naming both files", "[assets][obj]") {
    TempDir dir("obj");
    write_text(dir.file("m.mtl"), "newmtl m\nmap_Kd nowhere.png\n");
    std::string path = write_text(dir.file("needs_tex.obj"),
                                  "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
    require_input_error([&] { facet::load_obj(path); }, "needs_tex.obj");
    require_input_error([&] { facet::load_obj(path); }, "nowhere.png");
}

TEST_CASE("OBJ material libraries: spaces in names, backslashes, odd folders", "[assets][obj]") {
    TempDir dir("obj");
    SECTION("usemtl with a name containing spaces") {
        write_text(dir.file("spaced.mtl"),
                   "newmtl Matte Red  Paint\nKd 1 0 0\nnewmtl Matte\nKd 0 1 0\n");
        std::string path =
            write_text(dir.file("spaced.obj"),
                       "mtllib spaced.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                       "usemtl   Matte Red  Paint  \nf 1 2 3\nusemtl Matte\nf 3 2 1\n");
        facet::Mesh mesh = facet::load_obj(path);
        check_sane(mesh);
        std::map<std::string, glm::vec3> colour;
        for (const auto& part : mesh.parts)
            colour[material_of(mesh, part).name] = material_of(mesh, part).color;
        REQUIRE(colour.size() == 2);
        REQUIRE(colour.count("Matte Red Paint"));
        CHECK(colour["Matte Red Paint"] == glm::vec3(1, 0, 0));
        REQUIRE(colour.count("Matte"));
        CHECK(colour["Matte"] == glm::vec3(0, 1, 0));
    }
    SECTION("mtllib written with backslashes, in a folder whose name has a colon") {
        write_text(dir.file("a:b/libs/blue.mtl"), "newmtl blue\nKd 0 0 1\n");
        std::string path = write_text(
            dir.file("a:b/model.obj"),
            "mtllib .\\libs\\blue.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl blue\nf 1 2 3\n");
        facet::Mesh mesh = facet::load_obj(path);
        REQUIRE(mesh.parts.size() == 1);
        CHECK(material_of(mesh, mesh.parts[0]).name == "blue");
        CHECK(material_of(mesh, mesh.parts[0]).color == glm::vec3(0, 0, 1));
    }
}
