// One manifest reader checks every manifest for every command (the
// reliability issue, item 7): render resuming into a folder, compare,
// merge and video refuse the same invalid manifests with exit 2, naming
// the file and the value; render never replaces a manifest.json that is
// not facet's; compare -q still prints errors, and masks that leave out
// every pixel are no pass.
#include <catch2/catch.hpp>

#include <functional>

#include "compare_support.hpp"
#include "farm_support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

// A run of three frames (colour PNG and EXR, depth) in DIR/spin.
std::string three_frames(const TempDir& dir) {
    write_text(dir.file("spin.yaml"), R"(
output: { size: [32, 18], frames: "1-3", passes: [color, depth], formats: [png, exr] }
camera: { orbit: { radius: 4, turns: 1 } }
lights: [ { type: directional, direction: [-1, -1, -1] } ]
objects: [ { primitive: { type: torus }, material: { color: [0.8, 0.4, 0.2] } } ]
)");
    const RunResult r = run_facet("render " + shell_quote(dir.file("spin.yaml")) + " -q -o " +
                                  shell_quote(dir.file("run")));
    REQUIRE(r.exit_code == 0);
    return dir.file("run/spin");
}

// A copy of the run, as DIR/NAME/spin, whose manifest `edit` changed.
std::string edited(const TempDir& dir, const std::string& run, const std::string& name,
                   const std::function<void(nlohmann::json&)>& edit) {
    const std::string copy = dir.file(name + "/spin");
    std::filesystem::remove_all(dir.file(name));
    std::filesystem::create_directories(dir.file(name));
    copy_folder(run, copy);
    nlohmann::json m = read_json(copy + "/manifest.json");
    edit(m);
    write_text(copy + "/manifest.json", m.dump(2));
    return copy;
}

}  // namespace

TEST_CASE("render, compare, merge and video refuse the same invalid manifests with exit 2",
          "[manifest][cli]") {
    TempDir dir("manifest-checks");
    const std::string run = three_frames(dir);
    const std::vector<std::pair<std::string, std::function<void(nlohmann::json&)>>> cases = {
        {"version 99", [](nlohmann::json& m) { m["manifest_version"] = 99; }},
        {"size [0, 0]",
         [](nlohmann::json& m) {
             m["size"] = {0, 0};
         }},
        {"fps 0", [](nlohmann::json& m) { m["fps"] = 0; }},
        {"pass 'evil'", [](nlohmann::json& m) { m["files"][0]["pass"] = "evil"; }},
        {"format 'tiff'", [](nlohmann::json& m) { m["files"][0]["format"] = "tiff"; }},
        {"tonemap 'sepia'", [](nlohmann::json& m) { m["display"]["tonemap"] = "sepia"; }},
        {"listed twice", [](nlohmann::json& m) { m["files"].push_back(m["files"][0]); }},
        {"leaves the manifest's folder",
         [](nlohmann::json& m) { m["files"][0]["path"] = "../../spin.yaml"; }},
        {"leaves the manifest's folder",
         [](nlohmann::json& m) { m["files"][0]["path"] = "/etc/passwd"; }},
    };
    int n = 0;
    for (const auto& [needle, edit] : cases) {
        const std::string name = "bad" + std::to_string(n++);
        const std::string bad = edited(dir, run, name, edit);
        INFO(needle);
        for (const std::string& command :
             {"merge " + shell_quote(bad), "compare " + shell_quote(run) + " " + shell_quote(bad),
              "video " + shell_quote(bad) + " " + shell_quote(dir.file("m.mp4")),
              "render " + shell_quote(dir.file("spin.yaml")) + " -o " +
                  shell_quote(dir.file(name)) + " --overwrite"}) {
            INFO(command);
            const RunResult r = run_facet(command);
            INFO(r.output);
            CHECK(r.exit_code == 2);
            CHECK_THAT(r.output, Contains("manifest.json") && Contains(needle));
        }
    }
    CHECK_FALSE(std::filesystem::exists(dir.file("m.mp4")));
}

TEST_CASE("render never replaces a manifest.json that is not facet's", "[manifest][cli]") {
    TempDir dir("manifest-foreign");
    three_frames(dir);
    const std::string foreign = R"({"name": "my web app"})";
    write_text(dir.file("run/spin/manifest.json"), foreign);
    for (const char* extra : {"", " --overwrite"}) {
        INFO(extra);
        const RunResult r = run_facet("render " + shell_quote(dir.file("spin.yaml")) + " -o " +
                                      shell_quote(dir.file("run")) + extra);
        INFO(r.output);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("not a facet manifest") && Contains("move it away"));
        CHECK(read_file(dir.file("run/spin/manifest.json")) == foreign);
    }
}

TEST_CASE("compare -q prints a file it cannot read, and exits 4", "[compare][cli]") {
    TempDir dir("compare-quiet-error");
    const std::string run = three_frames(dir);
    const std::string damaged = edited(dir, run, "damaged", [](nlohmann::json&) {});
    write_text(damaged + "/color.0002.png", "not a PNG");
    refresh_manifest_hashes(damaged);
    const RunResult r =
        run_facet("compare -q " + shell_quote(run) + " " + shell_quote(damaged) + " --no-report");
    INFO(r.output);
    CHECK(r.exit_code == 4);
    CHECK_THAT(r.output, Contains("error:") && Contains("color.0002.png"));
}

TEST_CASE("masks that leave out every pixel compare nothing, which is no pass", "[compare][cli]") {
    TempDir dir("compare-mask-all");
    const std::string run = three_frames(dir);
    const std::string changed = edited(dir, run, "changed", [](nlohmann::json&) {});
    edit_png(changed + "/color.0001.png", changed + "/color.0001.png",
             [](std::vector<uint8_t>& samples, int, int) {
                 for (uint8_t& s : samples) s = static_cast<uint8_t>(255 - s);
             });
    refresh_manifest_hashes(changed);
    const RunResult r = run_facet("compare " + shell_quote(run) + " " + shell_quote(changed) +
                                  " --no-report --mask 0,0,32,18");
    INFO(r.output);
    CHECK(r.exit_code == 3);
    CHECK_THAT(r.output, Contains("0001.png") && Contains("nothing was compared"));
}

TEST_CASE("video refuses a manifest whose frame lacks the colour PNG its other frames have",
          "[video][cli]") {
    TempDir dir("video-missing-frame");
    const std::string run = three_frames(dir);
    const std::string holed = edited(dir, run, "holed", [](nlohmann::json& m) {
        nlohmann::json kept = nlohmann::json::array();
        for (const auto& f : m["files"])
            if (!(f["frame"] == 1 && f["pass"] == "color" && f["format"] == "png"))
                kept.push_back(f);
        m["files"] = kept;
    });
    const RunResult r =
        run_facet("video " + shell_quote(holed) + " " + shell_quote(dir.file("m.mp4")));
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("frame 1") && Contains("no colour PNG"));
    CHECK_FALSE(std::filesystem::exists(dir.file("m.mp4")));
}
