// The facet command line as a user runs it: exit codes (README, "Using it"),
// the manifest and its files, overrides, and what it prints.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

using Catch::Contains;
using facet::test::read_file;
using facet::test::run_facet;
using facet::test::TempDir;
using facet::test::write_text;
namespace fs = std::filesystem;

namespace {

// The brief's tiny turntable: a cube and a light, 64x48, two frames.
const char* kTinyScene = R"(output:
  size: [64, 48]
  frames: 1-2
camera:
  position: [2, 2, 3]
lights:
  - type: directional
    direction: [-1, -1, -1]
objects:
  - name: box
    primitive: cube
    spin:
      turns: 0.25
)";

std::string shell_quoted(const std::string& s) {
    return "'" + s + "'";
}

nlohmann::json read_json(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

// Every regular file under `dir`, recursively (none if it does not exist).
std::vector<std::string> files_under(const std::string& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    if (!fs::exists(dir, ec)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out.push_back(e.path().string());
    return out;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// Frame numbers listed in a manifest's "frames".
std::vector<int> manifest_frames(const nlohmann::json& manifest) {
    std::vector<int> out;
    for (const auto& f : manifest.at("frames")) out.push_back(f.at("frame").get<int>());
    return out;
}

struct Rendered {
    facet::test::RunResult run;
    std::string out_dir;
    std::string manifest_path;
};

Rendered render(const TempDir& dir, const std::string& scene, const std::string& extra) {
    Rendered r;
    r.out_dir = dir.file("out");
    r.run = run_facet("render " + shell_quoted(scene) + " --out " + shell_quoted(r.out_dir) +
                      " --threads 1 " + extra);
    r.manifest_path = (fs::path(r.out_dir) / fs::path(scene).stem() / "manifest.json").string();
    return r;
}

}  // namespace

TEST_CASE("render writes the frames and a manifest that describes them", "[cli]") {
    TempDir dir("cli");
    std::string scene = write_text(dir.file("turntable.yaml"), kTinyScene);
    Rendered r = render(dir, scene, "");
    INFO(r.run.output);
    REQUIRE(r.run.exit_code == 0);
    REQUIRE(fs::is_regular_file(r.manifest_path));

    nlohmann::json m = read_json(r.manifest_path);
    // The scene's path relative to the manifest's folder.
    CHECK((fs::path(r.manifest_path).parent_path() / m.at("scene").get<std::string>())
              .lexically_normal() == fs::path(scene).lexically_normal());
    CHECK(m.at("style").is_string());
    CHECK(m.at("size") == nlohmann::json::array({64, 48}));
    CHECK(manifest_frames(m) == std::vector<int>{1, 2});
    // Timings are in their own block; frames list only what was rendered.
    for (const auto& f : m.at("frames")) CHECK_FALSE(f.contains("render_ms"));
    for (const auto& f : m.at("timings").at("frames")) {
        CHECK(f.at("render_ms").get<double>() >= 0);
        CHECK(f.at("encode_ms").get<double>() >= 0);
    }

    // The default output is one colour PNG per frame.
    const auto& files = m.at("files");
    REQUIRE(files.size() == 2);
    std::set<int> frames_with_files;
    const fs::path folder = fs::path(r.manifest_path).parent_path();
    for (const auto& f : files) {
        std::string rel = f.at("path").get<std::string>();
        CAPTURE(rel);
        CHECK(fs::path(rel).is_relative());
        CHECK(f.at("pass") == "color");
        CHECK(f.at("format") == "png");
        frames_with_files.insert(f.at("frame").get<int>());
        std::string file = (folder / rel).string();
        REQUIRE(fs::is_regular_file(file));
        const std::string bytes = read_file(file);
        CHECK(f.at("sha256") == facet::sha256_hex(bytes.data(), bytes.size()));
        auto png = facet::read_png(file);
        CHECK(png.width == 64);
        CHECK(png.height == 48);
    }
    CHECK(frames_with_files == std::set<int>{1, 2});

    // Nothing but the frames and the manifest: no temporary files left over.
    auto written = files_under(r.out_dir);
    CHECK(written.size() == 3);
    for (const auto& path : written) CHECK_THAT(path, !Contains(".facet-tmp."));
}

TEST_CASE("the same frames come out bit-identical for any thread count", "[cli]") {
    TempDir dir("cli");
    std::string scene = write_text(dir.file("threads.yaml"), kTinyScene);
    std::vector<std::string> digests[2];
    int i = 0;
    for (const char* threads : {"1", "2"}) {
        std::string out = dir.file(std::string("out") + threads);
        auto run = run_facet("render " + shell_quoted(scene) + " --out " + shell_quoted(out) +
                             " --threads " + threads + " -q");
        REQUIRE(run.exit_code == 0);
        nlohmann::json m = read_json(out + "/threads/manifest.json");
        for (const auto& f : m.at("files")) digests[i].push_back(f.at("sha256").get<std::string>());
        ++i;
    }
    CHECK(digests[0].size() == 2);
    CHECK(digests[0] == digests[1]);
}

TEST_CASE("the --size and -D options change what the scene file says", "[cli]") {
    TempDir dir("cli");
    std::string scene = write_text(dir.file("sized.yaml"), kTinyScene);
    // Renders with `args`, which must succeed; returns the run and its first PNG.
    auto render_ok = [&](const std::string& args) {
        Rendered r = render(dir, scene, args);
        INFO(r.run.output);
        REQUIRE(r.run.exit_code == 0);
        nlohmann::json m = read_json(r.manifest_path);
        REQUIRE(!m.at("files").empty());
        auto png = facet::read_png(
            (fs::path(r.manifest_path).parent_path() / m["files"][0]["path"].get<std::string>())
                .string());
        return std::make_pair(r, png);
    };

    SECTION("--size") {
        auto [r, png] = render_ok("--size 32x24");
        CHECK(png.width == 32);
        CHECK(png.height == 24);
        CHECK(read_json(r.manifest_path).at("size") == nlohmann::json::array({32, 24}));
    }
    SECTION("-D after the scene") {
        auto [r, png] = render_ok("-D 'output.size=[40, 30]' -D output.frames=3");
        CHECK(png.width == 40);
        CHECK(png.height == 30);
        CHECK(manifest_frames(read_json(r.manifest_path)) == std::vector<int>{3});
    }
    SECTION("-D before the scene takes one value, not the scene's name too") {
        std::string out = dir.file("out");
        auto run = run_facet("render -D 'output.size=[40, 30]' " + shell_quoted(scene) + " --out " +
                             shell_quoted(out) + " --threads 1");
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        auto png = facet::read_png(out + "/sized/color.0001.png");
        CHECK(png.width == 40);
    }
    SECTION("-D is applied after --size") {
        auto [r, png] = render_ok("--size 32x24 -D 'output.size=[20, 10]'");
        CHECK(png.width == 20);
        CHECK(png.height == 10);
    }
}

// --style's value reaches the scene reader as a YAML string: quotes,
// backslashes and colons in a file's path are the path's own.
TEST_CASE("a --style preset file may have quotes, a backslash and a colon in its path", "[cli]") {
    TempDir dir("cli-style-path");
    std::string scene = write_text(dir.file("s.yaml"), kTinyScene);
    const std::string style =
        write_text(dir.file("my \"look\" \\ v2: final.yaml"), "extends: toon\ncels: 3\n");
    const auto r = facet::test::run_command("'" + facet::test::facet_executable() + "' validate '" +
                                            scene + "' --style '" + style + "' 2>&1");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    const auto bad =
        facet::test::run_command("'" + facet::test::facet_executable() + "' validate '" + scene +
                                 "' --style '" + dir.file("no \"such\".yaml") + "' 2>&1");
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.output, Contains("no \"such\""));
}

TEST_CASE("the --frames option renders only the frames it names", "[cli]") {
    TempDir dir("cli");
    std::string text = kTinyScene;
    text.replace(text.find("frames: 1-2"), 11, "frames: 1-4");
    std::string scene = write_text(dir.file("subset.yaml"), text);
    Rendered r = render(dir, scene, "--frames 4,2");
    INFO(r.run.output);
    REQUIRE(r.run.exit_code == 0);
    nlohmann::json m = read_json(r.manifest_path);
    CHECK(manifest_frames(m) == std::vector<int>{2, 4});
    std::set<int> file_frames;
    for (const auto& f : m.at("files")) file_frames.insert(f.at("frame").get<int>());
    CHECK(file_frames == std::set<int>{2, 4});
    CHECK(files_under(r.out_dir).size() == 3);  // two frames and the manifest

    SECTION("a second piece of the sequence joins the same manifest") {
        Rendered again = render(dir, scene, "--frames 1-3:2");
        REQUIRE(again.run.exit_code == 0);
        CHECK(manifest_frames(read_json(again.manifest_path)) == std::vector<int>{1, 2, 3, 4});
        CHECK(files_under(r.out_dir).size() == 5);
    }
}

TEST_CASE("invalid input exits with code 2 and writes nothing", "[cli]") {
    TempDir dir("cli");
    std::string scene = write_text(dir.file("good.yaml"), kTinyScene);
    const std::string bad_text = std::string(kTinyScene) + "    material:\n      shininess: -3\n";
    std::string bad_scene = write_text(dir.file("bad.yaml"), bad_text);
    std::string out = dir.file("out");

    struct Case {
        const char* name;
        std::string args;
        std::string says;  // part of what is printed
    };
    std::vector<Case> cases = {
        {"zero width", "--size 0x24", "--size"},
        {"size without height", "--size 64x", "--size"},
        {"size in words", "--size big", "--size"},
        {"size too large", "--size 100000x10", "--size"},
        {"reversed frames", "--frames 5-1", "--frames"},
        {"frames not numbers", "--frames one", "--frames"},
        {"zero step", "--frames 1-4:0", "--frames"},
        {"-D without '='", "-D camera.fov", "-D camera.fov"},
        {"-D without a key", "-D =30", "-D =30"},
        {"-D value out of range", "-D camera.fov=500", "command line -D camera.fov=500"},
        {"-D unknown key", "-D camera.zoom=2", "camera.zoom"},
        {"unknown option", "--bogus", "bogus"},
        {"unknown style", "--style no-such-style", "no-such-style"},
    };
    for (const auto& c : cases) {
        DYNAMIC_SECTION(c.name) {
            auto run = run_facet("render " + shell_quoted(scene) + " --out " + shell_quoted(out) +
                                 " " + c.args);
            INFO(run.output);
            CHECK(run.exit_code == 2);
            CHECK_THAT(run.output, Contains(c.says));
            CHECK(files_under(out).empty());
        }
    }
    SECTION("missing scene file") {
        std::string missing = dir.file("missing.yaml");
        auto run = run_facet("render " + shell_quoted(missing) + " --out " + shell_quoted(out));
        INFO(run.output);
        CHECK(run.exit_code == 2);
        CHECK_THAT(run.output, Contains(missing));
        CHECK(files_under(out).empty());
    }
    SECTION("invalid scene names file, line, column and key") {
        auto run = run_facet("render " + shell_quoted(bad_scene) + " --out " + shell_quoted(out));
        INFO(run.output);
        CHECK(run.exit_code == 2);
        // "      shininess: -3" is the last line (15); '-' is in column 18.
        CHECK_THAT(run.output, Contains(bad_scene + ":15:18"));
        CHECK_THAT(run.output, Contains("objects.0.material.shininess"));
        CHECK(files_under(out).empty());
    }
    SECTION("no scene at all") {
        auto run = run_facet("render --out " + shell_quoted(out));
        CHECK(run.exit_code == 2);
        CHECK(files_under(out).empty());
    }
    SECTION("no command") {
        CHECK(run_facet("").exit_code == 2);
        CHECK(run_facet("paint " + shell_quoted(scene)).exit_code == 2);
    }
}

TEST_CASE("validate checks a scene and writes nothing", "[cli]") {
    TempDir dir("cli");
    std::string scene = write_text(dir.file("validate_only_scene.yaml"), kTinyScene);
    const std::string bad_text = "objects:\n  - primitive: cube\n    scale: [1, 0, 1]\n";
    std::string bad = write_text(dir.file("validate_only_bad.yaml"), bad_text);

    auto ok = run_facet("validate " + shell_quoted(scene));
    INFO(ok.output);
    CHECK(ok.exit_code == 0);
    CHECK_THAT(ok.output, Contains("ok"));
    // Overrides and frame lists are checked too.
    CHECK(
        run_facet("validate " + shell_quoted(scene) + " -D camera.fov=30 --frames 1-2").exit_code ==
        0);
    CHECK(run_facet("validate " + shell_quoted(scene) + " -D camera.fov=0").exit_code == 2);
    CHECK(run_facet("validate " + shell_quoted(scene) + " --frames 2-1").exit_code == 2);
    // The threads a render would use, checked as render checks them.
    CHECK(run_facet("validate " + shell_quoted(scene) + " --threads 1").exit_code == 0);
    const auto threads = run_facet("validate " + shell_quoted(scene) + " --threads 300");
    CHECK(threads.exit_code == 2);
    CHECK_THAT(threads.output, Contains("--threads"));

    auto fail = run_facet("validate " + shell_quoted(bad));
    CHECK(fail.exit_code == 2);
    CHECK_THAT(fail.output, Contains(bad + ":3:12") && Contains("objects.0.scale"));

    // Only the two scene files are in their folder, and no output folder
    // appeared where facet ran.
    CHECK(files_under(dir.path()).size() == 2);
    CHECK_FALSE(fs::exists("out/validate_only_scene"));
    CHECK_FALSE(fs::exists("out/validate_only_bad"));
}

TEST_CASE("info describes a mesh file", "[cli]") {
    TempDir dir("cli");
    // One triangle and one quad: 1 + 2 = 3 triangles, 6 distinct vertices.
    std::string mesh = write_text(dir.file("shape.obj"),
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "v 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\n"
                                  "f 1 2 3\n"
                                  "f 4 5 6 7\n");
    auto run = run_facet("info " + shell_quoted(mesh));
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    bool found = false;
    for (const auto& line : lines_of(run.output)) {
        if (line.rfind("triangles:", 0) != 0) continue;
        found = true;
        CHECK(std::stoi(line.substr(10)) == 3);
    }
    CHECK(found);
    CHECK_THAT(run.output, Contains("[0, 0, 0] .. [3, 1, 0]"));

    auto missing = run_facet("info " + shell_quoted(dir.file("none.obj")));
    CHECK(missing.exit_code == 2);
    CHECK_THAT(missing.output, Contains("none.obj"));
}

TEST_CASE("what render prints", "[cli]") {
    TempDir dir("cli");
    std::string scene = write_text(dir.file("printing.yaml"), kTinyScene);

    SECTION("--quiet prints nothing on success") {
        Rendered r = render(dir, scene, "--quiet");
        CHECK(r.run.exit_code == 0);
        CHECK(r.run.output.empty());
        CHECK(fs::is_regular_file(r.manifest_path));
        Rendered q = render(dir, scene, "-q");
        CHECK(q.run.exit_code == 0);
        CHECK(q.run.output.empty());
    }
    SECTION("--quiet still reports errors") {
        Rendered r = render(dir, scene, "--quiet --size 0x0");
        CHECK(r.run.exit_code == 2);
        CHECK_FALSE(r.run.output.empty());
    }
    SECTION("output that is not a terminal gets one line per frame") {
        // run_facet reads through a pipe, so this is the non-terminal case.
        Rendered r = render(dir, scene, "");
        INFO(r.run.output);
        REQUIRE(r.run.exit_code == 0);
        std::vector<int> frames;
        for (const auto& line : lines_of(r.run.output)) {
            CHECK(line.find('\r') == std::string::npos);  // no in-place redraws
            // "[0:00:00] frame 1 (1/2, 50%) ...": elapsed time first.
            const size_t at = line.find("] frame ");
            if (line.rfind("[", 0) == 0 && at != std::string::npos)
                frames.push_back(std::stoi(line.substr(at + 8)));
        }
        CHECK(frames == std::vector<int>{1, 2});
    }
}

TEST_CASE("an output folder that cannot be made is an I/O failure (exit code 4)", "[cli]") {
    TempDir dir("cli");
    std::string scene = write_text(dir.file("blocked.yaml"), kTinyScene);
    std::string blocker = write_text(dir.file("not-a-folder"), "x");
    auto run = run_facet("render " + shell_quoted(scene) + " --out " + shell_quoted(blocker));
    INFO(run.output);
    CHECK(run.exit_code == 4);
    CHECK_THAT(run.output, Contains(blocker));
    CHECK(fs::is_regular_file(blocker));
}

TEST_CASE("the --help and --version options succeed", "[cli]") {
    auto version = run_facet("--version");
    CHECK(version.exit_code == 0);
    CHECK_THAT(version.output, Contains("facet"));
    auto help = run_facet("render --help");
    CHECK(help.exit_code == 0);
    CHECK_THAT(help.output, Contains("--frames") && Contains("--define"));
}
