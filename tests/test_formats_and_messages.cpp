// Formats told by their bytes, empty option values, and messages a user
// can read (the reliability issue, item 9).
#include <catch2/catch.hpp>

#include <cstring>

#include "compare_support.hpp"
#include "support.hpp"
#include "turntable_support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

std::string in(const TempDir& dir, const std::string& args) {
    return "cd " + shell_quote(dir.path()) + " && " + shell_quote(facet_executable()) + " " + args +
           " 2>&1";
}

}  // namespace

TEST_CASE("a binary STL under any name is read as STL, whatever its header says",
          "[assets][turntable]") {
    TempDir dir("stl-any-name");
    const auto cube = box_triangles({-1, -1, -1}, {1, 1, 1});
    write_binary_stl(dir.file("cube.dat"), cube);
    // Blender's binary STL may start its header with "solid": the size
    // tells it from ASCII. Named .bin, as a download may be.
    std::string blender = read_file(write_binary_stl(dir.file("tmp.stl"), cube));
    std::memcpy(blender.data(), "solid Exported from Blender", 27);
    write_text(dir.file("model.bin"), blender);
    for (const char* name : {"cube.dat", "model.bin"}) {
        INFO(name);
        const RunResult info = run_command(in(dir, std::string("info --json ") + name));
        INFO(info.output);
        REQUIRE(info.exit_code == 0);
        CHECK(nlohmann::json::parse(info.output)["triangles"] == cube.size() / 3);
        const RunResult r =
            run_command(in(dir, std::string("render ") + name + " -f 1 --size 32x24 -q -o out"));
        INFO(r.output);
        CHECK(r.exit_code == 0);
    }
}

TEST_CASE("an empty value for a turntable option is refused, not taken as the default",
          "[turntable][cli]") {
    TempDir dir("empty-values");
    write_binary_stl(dir.file("cube.stl"), box_triangles({-1, -1, -1}, {1, 1, 1}));
    for (const char* option :
         {"--up", "--ground", "--environment", "--background", "--turns", "--elevation"}) {
        INFO(option);
        const RunResult r = run_command(
            in(dir, std::string("render cube.stl -f 1 --size 32x24 -o out ") + option + " ''"));
        INFO(r.output);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains(option));
        CHECK_FALSE(std::filesystem::exists(dir.file("out")));
    }
}

TEST_CASE("messages about damaged files and folders say what is wrong, briefly", "[assets][cli]") {
    TempDir dir("messages");
    write_binary_stl(dir.file("cube.stl"), box_triangles({-1, -1, -1}, {1, 1, 1}));
    SECTION("an empty or cut .glb") {
        write_text(dir.file("empty.glb"), "");
        write_text(dir.file("cut.glb"), std::string("glTF\x02\0\0\0\x0c\0\0\0", 12));
        for (const char* name : {"empty.glb", "cut.glb"}) {
            const RunResult r = run_command(in(dir, std::string("render ") + name + " -f 1"));
            INFO(r.output);
            CHECK(r.exit_code == 2);
            CHECK_THAT(r.output, Contains(name) && Contains("cannot read glTF"));
            CHECK_THAT(r.output, !Contains("vector::") && !Contains("_M_range_check"));
        }
    }
    SECTION("a folder given as the environment") {
        const RunResult r = run_command(
            in(dir, "render cube.stl -f 1 --environment " + shell_quote(dir.path()) + " -o out"));
        INFO(r.output);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("--environment") && Contains("cannot read '" + dir.path()) &&
                                 Contains("is a directory"));
    }
    SECTION("a glTF whose data: URI cannot be decoded: the URI is cut, not repeated whole") {
        const std::string uri =
            "data:application/octet-stream;base64," + std::string(200000, 'x') + "!";
        write_text(dir.file("data.gltf"),
                   R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12, "uri": ")" +
                       uri + R"("}], "meshes": [], "scenes": [{"nodes": []}]})");
        const RunResult r = run_command(in(dir, "info data.gltf"));
        INFO(r.output.substr(0, 400));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("data.gltf") && Contains("bytes)"));
        CHECK(r.output.size() < 1000);
    }
}

TEST_CASE("a file that crashes assimp's reader is an error naming it, and facet goes on",
          "[assets][untrusted]") {
    // An input the PLY harness found: assimp's ASCII reader writes past its
    // buffers on it and glibc aborts the process. assimp runs in a child
    // process (assets/isolated_call.hpp).
    const std::string file =
        source_path("tests/fuzz/regressions/ply/assimp-reader-20f7dae6046d.ply");
    const RunResult r = run_facet("info " + shell_quote(file));
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("assimp-reader-20f7dae6046d.ply: the reader crashed on it"));
    CHECK_THAT(r.output, !Contains("malloc()"));
}
