// Wavefront OBJ loading (src/assets/obj_loader.cpp), broken files of our
// own: bad indices, files without faces, missing files and unknown
// extensions end in a facet::Error (invalid input) naming the file, never in a
// crash or a half-read mesh.
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "asset_support.hpp"
#include "assets/mesh.hpp"

namespace fs = std::filesystem;
using namespace facet::test;

namespace {

struct BadFile {
    const char* name;
    const char* file;  // written, and named by the error
    std::string text;
};

void require_each_rejected(const std::vector<BadFile>& cases) {
    TempDir dir("obj");
    for (const auto& c : cases) {
        DYNAMIC_SECTION(c.name) {
            std::string path = write_text(dir.file(c.file), c.text);
            require_input_error([&] { facet::load_obj(path); }, c.file);
        }
    }
}

}  // namespace

TEST_CASE("OBJ face indices past the end are errors naming the file", "[assets][obj]") {
    const std::string verts = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    require_each_rejected({
        {"triangle", "bad_tri.obj", verts + "f 1 2 5\n"},
        {"quad, next to a valid face", "bad_quad.obj", verts + "f 1 2 3\nf 1 2 3 9\n"},
        {"pentagon", "bad_poly.obj", verts + "f 1 2 3 4 77\n"},
        {"huge index", "bad_huge.obj", verts + "f 1 2 2147483647\n"},
        {"negative index before the first vertex", "bad_neg.obj", verts + "f -5 1 2\n"},
        {"negative index before the first vertex in a quad", "bad_negquad.obj",
         verts + "f 1 2 3\nf -9 1 2 3\n"},
        {"index zero", "bad_zero.obj", verts + "f 0 1 2\n"},
    });
}

TEST_CASE("OBJ normal and texture indices past the end do not break loading", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(dir.file("odd_attr.obj"),
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
                                  "f 1/7/9 2/1/1 3/1/1\n");
    facet::Mesh mesh = facet::load_obj(path);  // the stray indices are ignored, not read
    check_sane(mesh);
    CHECK(mesh.triangle_count() == 1);
    for (const auto& n : mesh.parts[0].normals) CHECK(n.z == Approx(1.0f));
}

TEST_CASE("OBJ files without faces are errors", "[assets][obj]") {
    std::string garbage;
    uint32_t x = 12345;
    for (int i = 0; i < 4096; ++i) {
        x = x * 1664525u + 1013904223u;
        garbage += static_cast<char>(0x80 | (x >> 24));  // never ASCII, so never a keyword
    }
    require_each_rejected({
        {"empty file", "empty.obj", ""},
        {"only comments and blank lines", "comments.obj", "# nothing here\n\n   \n# at all\n"},
        {"only vertices", "verts.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
        {"points and lines", "lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\nl 1 2 3\n"},
        {"faces with fewer than three corners", "short.obj", "v 0 0 0\nv 1 0 0\nf 1 2\nf 1\nf\n"},
        {"binary garbage", "garbage.obj", garbage},
    });
}

TEST_CASE("OBJ missing file or folder is an error naming it", "[assets][obj]") {
    TempDir dir("obj");
    std::string missing = dir.file("no_such_model.obj");
    require_input_error([&] { facet::load_obj(missing); }, "no_such_model.obj");
    require_input_error([&] { facet::load_mesh(missing); }, "no_such_model.obj");
    fs::create_directories(dir.file("folder.obj"));
    require_input_error([&] { facet::load_mesh(dir.file("folder.obj")); }, "folder.obj");
}

TEST_CASE("load_mesh picks the OBJ loader by extension, ignoring case", "[assets][obj]") {
    TempDir dir("obj");
    std::string path = write_text(dir.file("UPPER.OBJ"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    facet::Mesh mesh = facet::load_mesh(path);
    CHECK(mesh.triangle_count() == 1);
    std::string other = write_text(dir.file("model.stl"), "solid x\nendsolid x\n");
    require_input_error([&] { facet::load_mesh(other); }, "model.stl");
    std::string none = write_text(dir.file("model"), "v 0 0 0\n");
    require_input_error([&] { facet::load_mesh(none); }, "model");
}
