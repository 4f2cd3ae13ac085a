// The regression workflow around `facet compare`: render --reference,
// --update-reference in each mode, --self-test, and the reports (JUnit XML,
// and the HTML page opened in headless chromium).
#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>

#include "compare_support.hpp"
#include "core/sha256.hpp"
#include "output/manifest.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

std::string hash_of(const std::string& path) {
    const std::string bytes = read_file(path);
    return sha256_hex(bytes.data(), bytes.size());
}

// REF: frames 1-2 at fov 40. NEW: frames 1-3 at fov 42, so frames 1-2 fail
// and frame 3 is not in the reference.
struct UpdateCase {
    TempDir dir{"compare-update"};
    std::string ref, candidate;
    UpdateCase() {
        ref = render_shapes(dir.file("ref"), "--frames 1-2 -D camera.fov=40", "color", "png");
        candidate = render_shapes(dir.file("new"), "--frames 1-3 -D camera.fov=42", "color", "png");
    }
    RunResult update(const std::string& mode) {
        return run_facet("compare " + shell_quote(ref) + " " + shell_quote(candidate) +
                         " --no-report --update-reference " + mode);
    }
};

// Every file the reference manifest lists has the hash it states.
void check_manifest_hashes(const std::string& dir, size_t files) {
    const Manifest m = read_manifest(dir + "/manifest.json");
    REQUIRE(m.files.size() == files);
    for (const ManifestFile& f : m.files) CHECK(f.sha256 == hash_of(dir + "/" + f.path));
}

// `facet render` arguments: frames 1-2 of shapes.yaml at 160x90, colour PNG
// only, into DIR/out, compared with the reference folder `ref`.
std::string render_against(const TempDir& dir, const std::string& ref) {
    return "render " + shell_quote(source_path("tests/scenes/shapes.yaml")) +
           " --size 160x90 --frames 1-2 --passes color --formats png --out " +
           shell_quote(dir.file("out")) + " --reference " + shell_quote(ref);
}

}  // namespace

TEST_CASE("compare workflow: --update-reference missing writes only what the reference lacks",
          "[compare]") {
    UpdateCase c;
    const std::string old1 = hash_of(c.ref + "/color.0001.png");
    const RunResult r = c.update("missing");
    INFO(r.output);
    CHECK(r.exit_code == 3);  // frames 1-2 still fail
    CHECK(r.output.find("updated main/color/0003.png") != std::string::npos);
    CHECK(r.output.find("updated main/color/0001.png") == std::string::npos);
    CHECK(hash_of(c.ref + "/color.0001.png") == old1);
    CHECK(hash_of(c.ref + "/color.0003.png") == hash_of(c.candidate + "/color.0003.png"));
    check_manifest_hashes(c.ref, 3);
}

TEST_CASE("compare workflow: --update-reference failed rewrites only the failures", "[compare]") {
    UpdateCase c;
    const RunResult r = c.update("failed");
    INFO(r.output);
    CHECK(r.exit_code == 3);  // frame 3 is still missing from the reference
    CHECK(r.output.find("updated main/color/0001.png") != std::string::npos);
    CHECK(r.output.find("updated main/color/0002.png") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(c.ref + "/color.0003.png"));
    CHECK(hash_of(c.ref + "/color.0001.png") == hash_of(c.candidate + "/color.0001.png"));
    check_manifest_hashes(c.ref, 2);
}

TEST_CASE("compare workflow: --update-reference all, then the same run passes", "[compare]") {
    UpdateCase c;
    const RunResult r = c.update("all");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("3 files updated (all)") != std::string::npos);
    const RunResult again = run_facet("compare " + shell_quote(c.ref) + " " +
                                      shell_quote(c.candidate) + " --no-report");
    INFO(again.output);
    CHECK(again.exit_code == 0);
    CHECK(again.output.find("3 identical") != std::string::npos);
}

TEST_CASE("compare workflow: render --reference compares, and creates a first reference",
          "[compare]") {
    TempDir dir("compare-render");
    const std::string ref = dir.file("reference");
    const std::string render = render_against(dir, ref);
    // No reference yet: missing mode creates it.
    const RunResult first = run_facet(render + " --update-reference missing");
    INFO(first.output);
    CHECK(first.exit_code == 0);
    CHECK(read_manifest(ref + "/manifest.json").files.size() == 2);
    // The same render again: identical.
    const RunResult same = run_facet(render);
    INFO(same.output);
    CHECK(same.exit_code == 0);
    CHECK(same.output.find("2 identical") != std::string::npos);
    // A changed camera fails, with the report beside NEW's manifest.
    // (Other settings into the same folder need --overwrite: the manifest
    // must not mix runs.)
    const RunResult changed = run_facet(render + " -D camera.fov=46 --overwrite");
    INFO(changed.output);
    CHECK(changed.exit_code == 3);
    CHECK(std::filesystem::exists(dir.file("out/shapes/compare/report.json")));
    CHECK(std::filesystem::exists(dir.file("out/shapes/compare/junit.xml")));
    // Bad thresholds stop the run before it renders.
    const RunResult bad = run_facet(render + " -t color.nope=1");
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("wrote") == std::string::npos);
    CHECK(run_facet(render + " --update-reference sometimes").exit_code == 2);
}

// Deleting a reference image by hand is how a snapshot is made again
// (Jest, pytest-regressions, Playwright): its manifest still lists it.
TEST_CASE("compare workflow: a reference image deleted by hand is missing, and missing rewrites it",
          "[compare]") {
    TempDir dir("compare-deleted");
    const std::string ref = dir.file("reference");
    const std::string render = render_against(dir, ref);
    REQUIRE(run_facet(render + " --update-reference missing").exit_code == 0);
    const std::string kept = hash_of(ref + "/color.0001.png");
    const std::string deleted = hash_of(ref + "/color.0002.png");
    std::filesystem::remove(ref + "/color.0002.png");

    const RunResult plain = run_facet(render);
    INFO(plain.output);
    CHECK(plain.exit_code == 3);  // a failure, not an unreadable reference (4)
    CHECK_THAT(plain.output, Contains("1 extra"));
    CHECK_THAT(plain.output, Contains("1 identical"));

    const RunResult again = run_facet(render + " --update-reference missing");
    INFO(again.output);
    CHECK(again.exit_code == 0);
    CHECK_THAT(again.output, Contains("updated main/color/0002.png"));
    CHECK(hash_of(ref + "/color.0002.png") == deleted);
    CHECK(hash_of(ref + "/color.0001.png") == kept);
    check_manifest_hashes(ref, 2);
}

TEST_CASE("compare workflow: --self-test tells neighbouring frames apart, with a margin",
          "[compare]") {
    TempDir dir("compare-self");
    const std::string ref = render_shapes(dir.file("ref"), "--frames 1-3", "color", "png");
    const RunResult r = run_facet("compare --self-test " + shell_quote(ref));
    INFO(r.output);
    CHECK(r.exit_code == 0);
    std::smatch m;
    REQUIRE(std::regex_search(
        r.output, m,
        std::regex(R"(2 told apart, 0 not, 0 identical; smallest margin x([0-9.e+]+))")));
    CHECK(std::stod(m[1]) > 1);
    // Thresholds that let anything through cannot tell them apart.
    const RunResult loose = run_facet("compare --self-test " + shell_quote(ref) +
                                      " -t color.fail_percent=100 -t color.ssim_min=0");
    INFO(loose.output);
    CHECK(loose.exit_code == 3);
    CHECK(loose.output.find("NOT told apart") != std::string::npos);
}

TEST_CASE("compare workflow: JUnit XML and the HTML report in headless chromium", "[compare]") {
    TempDir dir("compare-report");
    const std::string a = render_shapes(dir.file("a"), "--frames 1-3");
    // NEW: frame 2 differs at the camera, frames 1 and 3 are the same.
    const std::string b = dir.file("b");
    copy_folder(a, b);
    const std::string changed = render_shapes(dir.file("c"), "--frames 2 -D camera.fov=46");
    for (const char* name :
         {"color.0002.png", "color.0002.exr", "depth.0002.png", "depth.0002.exr"}) {
        std::filesystem::copy_file(changed + "/" + name, b + "/" + name,
                                   std::filesystem::copy_options::overwrite_existing);
    }
    refresh_manifest_hashes(b);
    const RunResult r = run_facet("compare " + shell_quote(a) + " " + shell_quote(b));
    INFO(r.output);
    REQUIRE(r.exit_code == 3);
    const std::string report = b + "/compare";

    // JUnit: well-formed (Python's XML parser), one case per file, the
    // failures as <failure>.
    const RunResult junit = run_command(
        "/usr/bin/python3 -c \"import sys, xml.etree.ElementTree as E; r = "
        "E.parse(sys.argv[1]).getroot(); "
        "print(len(r.findall('.//testcase')), len(r.findall('.//failure')))\" " +
        shell_quote(report + "/junit.xml") + " 2>&1");
    CHECK(junit.output == "12 4\n");

    // HTML: chromium loads it from disk with the network off, every image
    // resolves, and the first card is a failure.
    const RunResult dom = run_command(
        "chromium --headless --disable-gpu --no-sandbox --disable-extensions --no-first-run "
        "--proxy-server=127.0.0.1:9 --virtual-time-budget=5000 --dump-dom " +
        shell_quote("file://" + report + "/index.html") + " 2>/dev/null");
    INFO(dom.output.substr(0, 400));
    REQUIRE(dom.exit_code == 0);
    std::smatch m;
    REQUIRE(std::regex_search(dom.output, m, std::regex("data-images-loaded=\"([0-9]+)\"")));
    CHECK(std::stoi(m[1]) >= 16);  // 4 files x (REF, NEW, difference, heat)
    CHECK(dom.output.find("data-images-broken=\"0\"") != std::string::npos);
    const size_t first_card = dom.output.find("data-status=\"");
    REQUIRE(first_card != std::string::npos);
    CHECK(dom.output.compare(first_card, 18, "data-status=\"fail\"") == 0);
    CHECK(dom.output.find("<svg") != std::string::npos);  // the per-frame plot
    CHECK(dom.output.find("https://") == std::string::npos);
}

TEST_CASE("compare workflow: manifests cannot point outside their folder, nor lie", "[compare]") {
    TempDir dir("compare-hostile");
    const std::string a = render_shapes(dir.file("a"), "--frames 1", "color", "png");
    const std::string b = dir.file("b");
    copy_folder(a, b);
    write_text(dir.file("secret.txt"), "SECRET123");
    nlohmann::json m = read_json(b + "/manifest.json");
    m["files"][0]["path"] = "../secret.txt";
    write_text(b + "/manifest.json", m.dump(2));
    const RunResult outside = run_facet("compare " + shell_quote(a) + " " + shell_quote(b));
    CHECK(outside.exit_code == 2);  // an invalid manifest, as in every reader
    CHECK_THAT(outside.output, Contains("leaves the manifest's folder"));
    CHECK(read_file(dir.file("secret.txt")) == "SECRET123");

    // A file changed after the run no longer matches its manifest.
    const std::string c = dir.file("c");
    copy_folder(a, c);
    edit_png(c + "/color.0001.png", c + "/color.0001.png",
             [](std::vector<uint8_t>& s, int, int) { s[0] ^= 1; });
    const RunResult lie = run_facet("compare " + shell_quote(a) + " " + shell_quote(c));
    CHECK(lie.exit_code == 4);
    CHECK_THAT(lie.output, Contains("does not match the SHA-256 its manifest records"));
}

TEST_CASE("compare workflow: references with subfolders, and renders of some frames", "[compare]") {
    TempDir dir("compare-subfolders");
    const std::string scene = source_path("tests/scenes/shapes.yaml");
    const std::string render = "render " + shell_quote(scene) +
                               " --size 48x32 --passes color,depth --formats png "
                               "-D 'output.path=\"{scene}/{pass}/{frame}.{ext}\"' -o " +
                               shell_quote(dir.file("out")) + " --reference " +
                               shell_quote(dir.file("ref"));
    const RunResult first = run_facet(render + " --frames 1-3 --update-reference missing");
    INFO(first.output);
    REQUIRE(first.exit_code == 0);
    CHECK(std::filesystem::exists(dir.file("ref/depth/0002.png")));
    check_manifest_hashes(dir.file("ref"), 6);
    // Frame 2 alone: the reference's frames 1 and 3 are not missing.
    const RunResult one = run_facet(render + " -f 2");
    INFO(one.output);
    CHECK(one.exit_code == 0);
    CHECK_THAT(one.output, Contains("2 identical"));
}
