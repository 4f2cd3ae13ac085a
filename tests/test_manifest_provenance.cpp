// The manifest as the run's honest record (docs/scene-format.md,
// "manifest.json"): provenance, timings apart so identical runs list
// identical files, a refusal to mix runs of other settings, and the same
// facts inside each image file.
#include <catch2/catch.hpp>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"
#include "core/version.hpp"
#include "support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

std::string scene_path() {
    std::string path = "'";
    path += source_path("tests/scenes/shapes.yaml");
    path += "'";
    return path;
}

RunResult render_into(const std::string& out, const std::string& extra) {
    return run_facet("render " + scene_path() + " --size 48x32 -q -o '" + out + "' " + extra);
}

nlohmann::json manifest_of(const std::string& out) {
    std::ifstream in(out + "/shapes/manifest.json");
    return nlohmann::json::parse(in);
}

// The tEXt chunks of a PNG, keyword -> text.
std::map<std::string, std::string> png_text(const std::string& path) {
    const std::string bytes = read_file(path);
    std::map<std::string, std::string> text;
    size_t at = 8;
    while (at + 12 <= bytes.size()) {
        const uint32_t length =
            (uint32_t(uint8_t(bytes[at])) << 24) | (uint32_t(uint8_t(bytes[at + 1])) << 16) |
            (uint32_t(uint8_t(bytes[at + 2])) << 8) | uint32_t(uint8_t(bytes[at + 3]));
        const std::string type = bytes.substr(at + 4, 4);
        if (type == "tEXt") {
            const std::string body = bytes.substr(at + 8, length);
            const size_t nul = body.find('\0');
            text[body.substr(0, nul)] = body.substr(nul + 1);
        }
        at += 12 + length;
    }
    return text;
}

std::vector<double> numbers(const std::string& text) {
    std::istringstream in(text);
    std::vector<double> out;
    double v;
    while (in >> v) out.push_back(v);
    return out;
}

}  // namespace

TEST_CASE("manifest: provenance of the build and the command line", "[manifest][cli]") {
    TempDir dir("provenance");
    const RunResult r = render_into(dir.file("out"), "-f 1 -D camera.fov=30");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const nlohmann::json m = manifest_of(dir.file("out"));
    CHECK(m.at("manifest_version") == 2);
    CHECK(m["facet"]["version"] == facet::build_info().version);
    CHECK(m["facet"]["commit"] == facet::build_info().commit);
    CHECK(m["facet"]["build"].get<std::string>().find(facet::build_info().build_type) == 0);
    CHECK(m["output_template"] == "{scene}/{pass}.{frame}.{ext}");
    bool fov = false;
    for (const auto& o : m["overrides"])
        fov = fov || (o["key"] == "camera.fov" && o["value"] == "30" &&
                      o["origin"] == "command line -D camera.fov=30");
    CHECK(fov);
    const auto& line = m["timings"]["command_line"];
    REQUIRE(line.size() > 3);
    CHECK(line[1] == "render");
    for (const auto& f : m["files"]) CHECK(f["style"] == m["style"]);
    const RunResult version = run_facet("--version");
    CHECK_THAT(version.output, Contains("commit " + facet::build_info().commit));
    CHECK_THAT(version.output, Contains(facet::build_info().build_type));
}

TEST_CASE("manifest: identical runs give identical manifests but for the timings",
          "[manifest][cli]") {
    TempDir dir("identical");
    REQUIRE(render_into(dir.file("a"), "--frames 1-2 --threads 1").exit_code == 0);
    REQUIRE(render_into(dir.file("b"), "--frames 1-2 --threads 2").exit_code == 0);
    nlohmann::json a = manifest_of(dir.file("a")), b = manifest_of(dir.file("b"));
    CHECK(a["timings"] != b["timings"]);  // other threads, other command line
    a.erase("timings");
    b.erase("timings");
    CHECK(a == b);
}

TEST_CASE("manifest: a run with other settings is refused, or starts anew with --overwrite",
          "[manifest][cli]") {
    TempDir dir("mixed");
    const std::string out = dir.file("out");
    REQUIRE(render_into(out, "-f 1").exit_code == 0);
    // Same settings, another frame: one manifest for both.
    REQUIRE(render_into(out, "-f 2").exit_code == 0);
    CHECK(manifest_of(out)["frames"].size() == 2);
    const RunResult refused = render_into(out, "-f 3 --style toon");
    INFO(refused.output);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output, Contains("was written by a run with other settings"));
    CHECK_THAT(refused.output, Contains("style: 'blinn-phong' there, 'toon' now"));
    CHECK_THAT(refused.output, Contains("--overwrite"));
    CHECK_FALSE(std::filesystem::exists(out + "/shapes/color.0003.png"));
    CHECK(manifest_of(out)["frames"].size() == 2);
    // Another size is another setting too.
    CHECK(
        run_facet("render " + scene_path() + " --size 50x32 -q -f 3 -o '" + out + "'").exit_code ==
        2);
    const RunResult fresh = render_into(out, "-f 3 --style toon --overwrite");
    CHECK(fresh.exit_code == 0);
    const nlohmann::json m = manifest_of(out);
    CHECK(m["style"] == "toon");
    REQUIRE(m["frames"].size() == 1);
    CHECK(m["frames"][0]["frame"] == 3);
}

TEST_CASE("manifest: each image file carries the version, scene, camera and matrices",
          "[manifest][cli]") {
    TempDir dir("metadata");
    REQUIRE(render_into(dir.file("out"), "--frames 1-2 --passes color,depth --formats png,exr")
                .exit_code == 0);
    const std::string folder = dir.file("out/shapes");
    const auto one = png_text(folder + "/color.0001.png");
    const auto two = png_text(folder + "/color.0002.png");
    CHECK(one.at("Software") == "facet " + facet::build_info().version);
    CHECK(one.at("facet:scene") == "shapes");
    CHECK(one.at("facet:camera") == "main");
    CHECK(one.at("facet:frame") == "1");
    CHECK(numbers(one.at("facet:view")).size() == 16);
    CHECK(numbers(one.at("facet:projection")).size() == 16);
    // The camera orbits: the view changes, the projection does not.
    CHECK(one.at("facet:view") != two.at("facet:view"));
    CHECK(one.at("facet:projection") == two.at("facet:projection"));
    CHECK(png_text(folder + "/depth.0001.png").at("facet:view") == one.at("facet:view"));
    // The same facts in the EXR header.
    for (const char* name : {"color.0001.exr", "depth.0001.exr"}) {
        Imf::InputFile file((folder + "/" + name).c_str());
        const auto* view = file.header().findTypedAttribute<Imf::StringAttribute>("facet:view");
        REQUIRE(view);
        CHECK(view->value() == one.at("facet:view"));
        const auto* software = file.header().findTypedAttribute<Imf::StringAttribute>("Software");
        REQUIRE(software);
        CHECK(software->value() == one.at("Software"));
    }
}

TEST_CASE("manifest: equivalent runs merge, a file rewritten by a later run is listed once",
          "[manifest][cli]") {
    TempDir dir("merge-equivalent");
    const std::string out = dir.file("out");
    const std::string scene = source_path("tests/scenes/shapes.yaml");
    const std::string dotted =
        (std::filesystem::path(scene).parent_path() / "." / "shapes.yaml").string();
    // The scene typed two ways, the same overrides in another order.
    REQUIRE(run_facet("render '" + scene + "' --size 48x32 -q -o '" + out +
                      "' -f 1 -D camera.fov=40 -D output.samples=1")
                .exit_code == 0);
    const RunResult second = run_facet("render '" + dotted + "' --size 48x32 -q -o '" + out +
                                       "' -f 2 -D output.samples=1 -D camera.fov=40");
    INFO(second.output);
    CHECK(second.exit_code == 0);
    CHECK(manifest_of(out)["frames"].size() == 2);
    // validate does not look at out/ unless told to with -o.
    CHECK(run_facet("validate '" + scene + "'").exit_code == 0);

    // A template without {frame}: each run rewrites the same file.
    const std::string single = dir.file("single");
    const std::string args = "render '" + scene +
                             "' --size 48x32 -q -D 'output.path=\"{scene}/{pass}.{ext}\"' -o '" +
                             single + "' ";
    REQUIRE(run_facet(args + "-f 1").exit_code == 0);
    REQUIRE(run_facet(args + "-f 2").exit_code == 0);
    const nlohmann::json m = manifest_of(single);
    REQUIRE(m["files"].size() == 1);
    CHECK(m["files"][0]["frame"] == 2);
    const std::string bytes = read_file(single + "/shapes/color.png");
    CHECK(m["files"][0]["sha256"] == facet::sha256_hex(bytes.data(), bytes.size()));
}
