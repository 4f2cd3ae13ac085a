// The manifest's hashes are of the bytes that were rendered (the
// reliability issue, item 5): facet opens the scene file, or a model for
// its turntable, exactly once, hashes what it parsed, and tells a model's
// format from those bytes. Counted with strace, which sees every open.
#include <catch2/catch.hpp>

#include <filesystem>

#include "compare_support.hpp"
#include "core/sha256.hpp"
#include "support.hpp"
#include "turntable_support.hpp"

using namespace facet::test;

namespace {

// How many times `facet ARGS`, run in `dir`, opened `file` (its name as
// given), or -1 when strace cannot trace here.
int opens_of(const TempDir& dir, const std::string& args, const std::string& file) {
    const RunResult r = run_command("cd " + shell_quote(dir.path()) +
                                    " && strace -f -qq -e trace=open,openat -o trace.txt " +
                                    shell_quote(facet_executable()) + " " + args + " -q 2>&1");
    if (r.exit_code != 0) {
        INFO(r.output);
        if (r.output.find("ptrace") != std::string::npos) return -1;
        FAIL("facet " << args << " failed");
    }
    int count = 0;
    std::istringstream lines(read_file(dir.file("trace.txt")));
    for (std::string line; std::getline(lines, line);)
        if (line.find("\"" + file + "\"") != std::string::npos) ++count;
    return count;
}

std::string file_sha256(const std::string& path) {
    const std::string bytes = read_file(path);
    return facet::sha256_hex(bytes.data(), bytes.size());
}

}  // namespace

TEST_CASE("facet render MODEL opens the model once and records the SHA-256 of what it read",
          "[turntable][manifest]") {
    if (!have_command("strace")) FACET_SKIP("strace is not installed (scripts/setup.sh --tests)");
    TempDir dir("read-once-model");
    write_binary_stl(dir.file("cube.stl"), box_triangles({-1, -1, -1}, {1, 1, 1}));
    const int opens = opens_of(dir, "render cube.stl -f 1 --size 32x24 -o out", "cube.stl");
    if (opens < 0) FACET_SKIP("strace cannot trace processes here (ptrace is not permitted)");
    CHECK(opens == 1);
    CHECK(read_json(dir.file("out/cube/manifest.json"))["model"]["sha256"] ==
          file_sha256(dir.file("cube.stl")));
    // A binary STL under a name that is no format's: its first bytes say
    // it is a mesh, not a scene; then it is read once, as STL by its bytes.
    write_binary_stl(dir.file("tile.dat"), box_triangles({-1, -1, 0}, {1, 1, 0.1f}));
    CHECK(opens_of(dir, "render tile.dat -f 1 --size 32x24 -o out", "tile.dat") == 2);
    CHECK(read_json(dir.file("out/tile/manifest.json"))["model"]["sha256"] ==
          file_sha256(dir.file("tile.dat")));
}

TEST_CASE("facet render SCENE opens the scene file once and records the SHA-256 of what it read",
          "[manifest]") {
    if (!have_command("strace")) FACET_SKIP("strace is not installed (scripts/setup.sh --tests)");
    TempDir dir("read-once-scene");
    write_text(dir.file("once.yaml"), R"(
output: { size: [32, 18], frames: "1-2", passes: [color], formats: [png] }
camera: { position: [0, 0, 5] }
objects: [ { primitive: { type: cube } } ]
)");
    const int opens = opens_of(dir, "render once.yaml -o out", "once.yaml");
    if (opens < 0) FACET_SKIP("strace cannot trace processes here (ptrace is not permitted)");
    CHECK(opens == 1);
    const nlohmann::json m = read_json(dir.file("out/once/manifest.json"));
    CHECK(m["scene_sha256"] == file_sha256(dir.file("once.yaml")));
}
