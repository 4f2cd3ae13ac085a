// Several cameras from the command line: `--camera NAME[,NAME]|all`, output
// names with {camera} (docs/output-naming.md), template errors found before
// anything is written, and the manifest's camera entries.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using Catch::Contains;
using facet::test::line_col;
using facet::test::read_file;
using facet::test::run_facet;
using facet::test::TempDir;
using facet::test::write_text;
namespace fs = std::filesystem;

namespace {

// Two cameras looking at a cube from different sides; `extra_output` goes
// into the output mapping.
std::string two_camera_scene(const std::string& extra_output = "",
                             const std::string& frames = "1") {
    return "output:\n  size: [48, 36]\n  frames: " + frames + "\n" + extra_output +
           R"(cameras:
  - name: front
    position: [0, 1, 4]
  - name: side
    position: [4, 1, 0.5]
lights:
  - type: directional
    direction: [-1, -2, -1]
objects:
  - name: box
    primitive: cube
    rotate: [0, 20, 0]
)";
}

std::string shell_quoted(const std::string& s) {
    return "'" + s + "'";
}

// Every regular file under `dir`, relative to it, sorted.
std::vector<std::string> files_under(const std::string& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    if (!fs::exists(dir, ec)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out.push_back(fs::relative(e.path(), dir).string());
    std::sort(out.begin(), out.end());
    return out;
}

nlohmann::json read_json(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

struct Run {
    facet::test::RunResult result;
    std::string out;  // the --out folder
};

Run render(const TempDir& dir, const std::string& scene, const std::string& args,
           const std::string& out_name = "out") {
    Run r;
    r.out = dir.file(out_name);
    r.result = run_facet("render " + shell_quoted(scene) + " --out " + shell_quoted(r.out) +
                         " --threads 1 -q " + args);
    return r;
}

std::string sha_of(const std::string& path) {
    const std::string bytes = read_file(path);
    return facet::sha256_hex(bytes.data(), bytes.size());
}

}  // namespace

TEST_CASE("render --camera all puts each camera in its own folder", "[cli][camera]") {
    TempDir dir("cli-cams");
    const std::string scene = write_text(dir.file("pair.yaml"), two_camera_scene());
    Run r = render(dir, scene, "--camera all");
    INFO(r.result.output);
    REQUIRE(r.result.exit_code == 0);
    CHECK(files_under(r.out) == std::vector<std::string>{"pair/front/color.0001.png",
                                                         "pair/manifest.json",
                                                         "pair/side/color.0001.png"});
    // Two different views.
    CHECK(sha_of(r.out + "/pair/front/color.0001.png") !=
          sha_of(r.out + "/pair/side/color.0001.png"));

    // The manifest names the camera of each file, with paths relative to it.
    nlohmann::json m = read_json(r.out + "/pair/manifest.json");
    REQUIRE(m.at("files").size() == 2);
    std::set<std::string> cameras;
    for (const auto& f : m.at("files")) {
        const std::string camera = f.at("camera").get<std::string>();
        const std::string path = f.at("path").get<std::string>();
        cameras.insert(camera);
        CHECK(path == camera + "/color.0001.png");
        CHECK(f.at("sha256") == sha_of(r.out + "/pair/" + path));
    }
    CHECK(cameras == std::set<std::string>{"front", "side"});
    std::set<std::string> frame_cameras;
    for (const auto& f : m.at("frames")) frame_cameras.insert(f.at("camera").get<std::string>());
    CHECK(frame_cameras == cameras);

    SECTION("--camera side renders that camera alone, with the one-camera names") {
        Run one = render(dir, scene, "--camera side", "out-side");
        INFO(one.result.output);
        REQUIRE(one.result.exit_code == 0);
        CHECK(files_under(one.out) ==
              std::vector<std::string>{"pair/color.0001.png", "pair/manifest.json"});
        // The same image as the side camera's in the run of all cameras.
        CHECK(sha_of(one.out + "/pair/color.0001.png") ==
              sha_of(r.out + "/pair/side/color.0001.png"));
        nlohmann::json m1 = read_json(one.out + "/pair/manifest.json");
        REQUIRE(m1.at("files").size() == 1);
        CHECK(m1["files"][0].at("camera") == "side");
        CHECK(m1["files"][0].at("path") == "color.0001.png");
    }
    SECTION("no --camera renders the first camera with the one-camera names") {
        Run first = render(dir, scene, "", "out-first");
        INFO(first.result.output);
        REQUIRE(first.result.exit_code == 0);
        CHECK(files_under(first.out) ==
              std::vector<std::string>{"pair/color.0001.png", "pair/manifest.json"});
        CHECK(sha_of(first.out + "/pair/color.0001.png") ==
              sha_of(r.out + "/pair/front/color.0001.png"));
    }
    SECTION("--camera side,front renders both") {
        Run both = render(dir, scene, "--camera side,front", "out-both");
        INFO(both.result.output);
        REQUIRE(both.result.exit_code == 0);
        CHECK(files_under(both.out) == files_under(r.out));
    }
}

TEST_CASE("an unknown camera name is a usage error listing the cameras", "[cli][camera]") {
    TempDir dir("cli-cams");
    const std::string scene = write_text(dir.file("pair.yaml"), two_camera_scene());
    for (const char* args : {"--camera top", "--camera front,top"}) {
        INFO(args);
        Run r = render(dir, scene, args);
        INFO(r.result.output);
        CHECK(r.result.exit_code == 2);
        CHECK_THAT(r.result.output, Contains("'top'"));
        CHECK_THAT(r.result.output, Contains("front"));
        CHECK_THAT(r.result.output, Contains("side"));
        CHECK(files_under(r.out).empty());
    }
    auto validate = run_facet("validate " + shell_quoted(scene) + " --camera top");
    CHECK(validate.exit_code == 2);
    CHECK_THAT(validate.output, Contains("front"));
}

TEST_CASE("an output.path with {camera} renders every camera by default", "[cli][camera]") {
    TempDir dir("cli-cams");
    const std::string scene = write_text(
        dir.file("pair.yaml"), two_camera_scene("  path: \"shots/{camera}/f####.{ext}\"\n", "1-2"));
    Run r = render(dir, scene, "");
    INFO(r.result.output);
    REQUIRE(r.result.exit_code == 0);
    CHECK(files_under(r.out) ==
          std::vector<std::string>{"shots/front/f0001.png", "shots/front/f0002.png",
                                   "shots/manifest.json", "shots/side/f0001.png",
                                   "shots/side/f0002.png"});
    nlohmann::json m = read_json(r.out + "/shots/manifest.json");
    REQUIRE(m.at("files").size() == 4);
    for (const auto& f : m.at("files")) {
        const std::string path = f.at("path").get<std::string>();
        CAPTURE(path);
        CHECK(fs::path(path).is_relative());
        CHECK(path.rfind(f.at("camera").get<std::string>() + "/f000", 0) == 0);
        CHECK(f.at("sha256") == sha_of(r.out + "/shots/" + path));
    }
    // Naming one camera puts its manifest in its own folder.
    Run one = render(dir, scene, "--camera side", "out-side");
    INFO(one.result.output);
    REQUIRE(one.result.exit_code == 0);
    CHECK(files_under(one.out) == std::vector<std::string>{"shots/side/f0001.png",
                                                           "shots/side/f0002.png",
                                                           "shots/side/manifest.json"});
}

TEST_CASE("output templates that cannot work stop the run before anything is written",
          "[cli][camera]") {
    TempDir dir("cli-cams");
    SECTION("no {frame} with several frames") {
        const std::string text = two_camera_scene("  path: \"{scene}/{camera}.{ext}\"\n", "1-3");
        const std::string scene = write_text(dir.file("noframe.yaml"), text);
        Run r = render(dir, scene, "");
        INFO(r.result.output);
        CHECK(r.result.exit_code == 2);
        CHECK_THAT(r.result.output, Contains("noframe/front.png"));
        CHECK_THAT(r.result.output, Contains("{frame}"));
        CHECK_THAT(r.result.output, Contains(scene + ":" + line_col(text, "\"{scene}")));
        CHECK(files_under(r.out).empty());
        CHECK_FALSE(fs::exists(r.out));
        // One frame is fine with the same template.
        Run single = render(dir, scene, "--frames 2", "out-single");
        INFO(single.result.output);
        CHECK(single.result.exit_code == 0);
        CHECK(files_under(single.out) == std::vector<std::string>{"noframe/front.png",
                                                                  "noframe/manifest.json",
                                                                  "noframe/side.png"});
    }
    SECTION("no {camera} with two cameras") {
        const std::string text = two_camera_scene("  path: \"{scene}/{frame}.{ext}\"\n");
        const std::string scene = write_text(dir.file("nocam.yaml"), text);
        Run r = render(dir, scene, "--camera all");
        INFO(r.result.output);
        CHECK(r.result.exit_code == 2);
        CHECK_THAT(r.result.output, Contains("camera 'front'"));
        CHECK_THAT(r.result.output, Contains("camera 'side'"));
        CHECK_FALSE(fs::exists(r.out));
    }
    SECTION("invalid template text names file:line:col of output.path") {
        const std::string good = two_camera_scene("  path: \"{scene}/{fram}.{ext}\"\n");
        const std::string scene = write_text(dir.file("typo.yaml"), good);
        const std::string where = scene + ":" + line_col(good, "\"{scene}/{fram}");
        Run r = render(dir, scene, "");
        INFO(r.result.output);
        CHECK(r.result.exit_code == 2);
        CHECK_THAT(r.result.output, Contains(where));
        CHECK_THAT(r.result.output, Contains("'output.path'"));
        CHECK_THAT(r.result.output, Contains("did you mean '{frame}'"));
        CHECK_FALSE(fs::exists(r.out));

        // `facet validate` reports the same error.
        auto validate = run_facet("validate " + shell_quoted(scene));
        INFO(validate.output);
        CHECK(validate.exit_code == 2);
        CHECK_THAT(validate.output, Contains(where));
        CHECK_THAT(validate.output, Contains("'output.path'"));
        CHECK_THAT(validate.output, Contains("{fram}"));
    }
    SECTION("validate finds the missing {frame} too") {
        const std::string text = two_camera_scene("  path: \"{camera}.{ext}\"\n", "1-2");
        const std::string scene = write_text(dir.file("v.yaml"), text);
        auto validate = run_facet("validate " + shell_quoted(scene));
        INFO(validate.output);
        CHECK(validate.exit_code == 2);
        CHECK_THAT(validate.output, Contains(scene + ":" + line_col(text, "\"{camera}")));
        CHECK_THAT(validate.output, Contains("add {frame}"));
        // And passes once the frame is in the name.
        const std::string fixed = write_text(
            dir.file("v2.yaml"), two_camera_scene("  path: \"{camera}.{frame}.{ext}\"\n", "1-2"));
        auto ok = run_facet("validate " + shell_quoted(fixed));
        INFO(ok.output);
        CHECK(ok.exit_code == 0);
    }
}
