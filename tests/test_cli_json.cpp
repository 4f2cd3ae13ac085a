// Machine-readable output, parsed back: validate/info/styles --json,
// `styles NAME` resolved, and render --dry-run against what a render
// writes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

std::string shapes() {
    std::string path = "'";
    path += source_path("tests/scenes/shapes.yaml");
    path += "'";
    return path;
}

// stdout only: JSON must not be mixed with messages.
RunResult run_stdout(const std::string& args) {
    return run_command("'" + std::string(facet::test::facet_executable()) + "' " + args +
                       " 2>/dev/null");
}

}  // namespace

TEST_CASE("json: validate reports facts, or the error with its place", "[cli][json]") {
    const RunResult ok = run_stdout("validate " + shapes() + " --json -f 2");
    REQUIRE(ok.exit_code == 0);
    const auto j = nlohmann::json::parse(ok.output);
    CHECK(j["ok"] == true);
    CHECK(j["objects"] == 5);
    CHECK(j["frames"] == nlohmann::json::array({2}));
    CHECK(j["size"] == nlohmann::json::array({320, 240}));
    CHECK(j["warnings"].is_array());

    TempDir dir("json-validate");
    const std::string bad = write_text(dir.file("bad.yaml"), "camera:\n  fov: 500\n");
    const RunResult error = run_stdout("validate '" + bad + "' --json");
    CHECK(error.exit_code == 2);
    const auto e = nlohmann::json::parse(error.output);
    CHECK(e["ok"] == false);
    CHECK(e["exit_code"] == 2);
    REQUIRE(e["errors"].size() == 1);
    CHECK(e["errors"][0]["file"] == bad);
    CHECK(e["errors"][0]["line"] == 2);
    CHECK(e["errors"][0]["column"] == 8);
    CHECK(e["errors"][0]["key"] == "camera.fov");
    const RunResult override = run_stdout("validate " + shapes() + " --json -D camera.fov=-3");
    const auto o = nlohmann::json::parse(override.output);
    CHECK(o["errors"][0]["origin"] == "command line -D camera.fov=-3");
}

TEST_CASE("json: info and styles", "[cli][json]") {
    const RunResult info =
        run_stdout("info '" + source_path("scenes/assets/knot.glb") + "' --json");
    REQUIRE(info.exit_code == 0);
    const auto mesh = nlohmann::json::parse(info.output);
    CHECK(mesh["triangles"] == 23040);
    CHECK(mesh["bounds"]["min"].size() == 3);
    CHECK(mesh["materials"].size() >= 1);
    CHECK(mesh["loader"] == "tinygltf");

    // A Blender file with every kind of fact info gives, in text and JSON alike.
    const std::string features = source_path("tests/assets/blender/features.glb");
    const RunResult rich = run_stdout("info '" + features + "' --json");
    REQUIRE(rich.exit_code == 0);
    const auto f = nlohmann::json::parse(rich.output);
    CHECK(f["parts_with_vertex_colors"] == 1);
    REQUIRE(f["cameras"].size() == 1);
    CHECK(f["cameras"][0]["name"] == "Camera");
    CHECK(f["cameras"][0]["type"] == "perspective");
    REQUIRE(f["lights"].size() == 2);
    CHECK(f["lights"][0]["type"] == "point");
    CHECK(f["lights"][1]["type"] == "directional");
    REQUIRE(f["animations"].size() == 1);
    CHECK(f["animations"][0]["nodes"] == nlohmann::json::array({"Camera"}));
    bool glowing = false;
    for (const auto& m : f["materials"])
        if (m["name"] == "Glow") glowing = m["emissive"][0].get<double>() > 3.9;
    CHECK(glowing);
    const RunResult text = run_stdout("info '" + features + "'");
    for (const char* fact :
         {"loader:     tinygltf", "1 with vertex colours", "cameras:    1", "  - Camera: yfov",
          "lights:     2", "emissive [4, 2, 0]", "CameraAction: 1 s, 1 channel, drives Camera"})
        CHECK_THAT(text.output, Catch::Contains(fact));
    const RunResult obj =
        run_stdout("info '" + source_path("tests/scenes/open_tube.obj") + "' --json");
    CHECK(nlohmann::json::parse(obj.output)["loader"] == "facet");
    const std::string stl = "/usr/share/assimp/models/STL/Wuson.stl";
    if (std::filesystem::exists(stl))
        CHECK(nlohmann::json::parse(run_stdout("info '" + stl + "' --json").output)["loader"] ==
              "assimp");

    const RunResult styles = run_stdout("styles --json");
    REQUIRE(styles.exit_code == 0);
    const auto list = nlohmann::json::parse(styles.output);
    std::set<std::string> names;
    for (const auto& s : list) {
        names.insert(s["name"]);
        CHECK_FALSE(s["description"].get<std::string>().empty());
        CHECK_FALSE(s.contains("error"));
    }
    CHECK(names.count("toon"));
    for (const auto& s : list)
        if (s["name"] == "toon-outline") CHECK(s["extends"] == "toon");
}

TEST_CASE("styles NAME prints the preset with its extends chain applied", "[cli][json]") {
    const RunResult r = run_stdout("styles toon-outline");
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("# toon-outline: toon-outline <- toon"));
    CHECK_THAT(r.output, Contains("bands:"));       // from toon
    CHECK_THAT(r.output, Contains("silhouette:"));  // its own
    CHECK_THAT(r.output, !Contains("extends:"));
    const RunResult typo = run_facet("styles tooon");
    CHECK(typo.exit_code == 2);
    CHECK_THAT(typo.output, Contains("did you mean 'toon'?"));
}

TEST_CASE("render --dry-run lists exactly the files a render writes, and writes none",
          "[cli][json]") {
    TempDir dir("dry-run");
    const std::string out = dir.file("out");
    const std::string args =
        "render " + shapes() +
        " --size 32x24 --frames 1-2 --passes color,depth --formats png,exr -o '" + out + "'";
    const RunResult dry = run_stdout(args + " --dry-run");
    REQUIRE(dry.exit_code == 0);
    CHECK_FALSE(std::filesystem::exists(out));
    std::vector<std::string> listed;
    std::istringstream lines(dry.output);
    for (std::string line; std::getline(lines, line);) listed.push_back(line);
    REQUIRE(run_facet(args + " -q").exit_code == 0);
    std::vector<std::string> written;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(out))
        if (entry.is_regular_file()) written.push_back(entry.path().string());
    std::sort(listed.begin(), listed.end());
    std::sort(written.begin(), written.end());
    CHECK(listed == written);
    CHECK(listed.size() == 9);  // 2 frames x 2 passes x 2 formats, and the manifest
}
