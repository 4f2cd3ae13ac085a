// `facet styles` and `facet sheet` as a user runs them (docs/styles.md):
// the list of presets with their descriptions, contact sheets of presets
// and of one parameter's values, and their errors (exit code 2, no file).
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "job/labels.hpp"
#include "output/encoders.hpp"
#include "scene/scene_desc.hpp"
#include "support.hpp"

using Catch::Contains;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

// Runs a shell command line (facet with an environment of its own).
RunResult run_shell(const std::string& command) {
    RunResult result;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    const int status = ::pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

// `facet ARGS` with only the shipped presets (no user FACET_STYLE_PATH).
RunResult facet_shipped(const std::string& args) {
    return run_shell("env -u FACET_STYLE_PATH " + quoted(facet::test::facet_executable()) + " " +
                     args);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The line that lists preset `name`: the name, then at least two spaces.
std::string listed_line(const std::vector<std::string>& lines, const std::string& name) {
    for (const std::string& line : lines)
        if (line.rfind(name + "  ", 0) == 0) return line;
    return {};
}

// Contact sheet geometry (job/contact_sheet.cpp): labels at scale 2
// with 6 pixels of padding above and below, under each cell.
int label_band() {
    return facet::label_height(2) + 2 * 6;
}

// A small scene: the palette look on a sphere and a box over a floor.
const char* kSheetScene =
    R"(output: { size: [64, 48], frames: 1-2, background: [0.2, 0.2, 0.25, 1] }
style: palette
camera: { position: [0, 2, 5], target: [0, 0.4, 0], fov: 45 }
lights:
  - { type: directional, direction: [-1, -2, -1.5] }
objects:
  - name: ball
    primitive: sphere
    translate: [-0.6, 0.5, 0]
    material: { color: [0.85, 0.3, 0.2] }
  - name: box
    primitive: cube
    translate: [0.7, 0.5, 0]
    material: { color: [0.2, 0.5, 0.9] }
  - name: floor
    primitive: { type: plane, size: 6 }
)";

// Mean absolute difference of two cells (8-bit samples, every channel).
double cell_difference(const facet::DecodedPng& png, int cell_a_x, int cell_a_y, int cell_b_x,
                       int cell_b_y, int w, int h) {
    double sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < png.channels; ++c) {
                auto at = [&](int x0, int y0) {
                    const size_t p = static_cast<size_t>(y0 + y) * png.width + (x0 + x);
                    return static_cast<int>(png.samples[p * png.channels + c]);
                };
                sum += std::abs(at(cell_a_x, cell_a_y) - at(cell_b_x, cell_b_y));
            }
    return sum / (static_cast<double>(w) * h * png.channels);
}

}  // namespace

TEST_CASE("facet styles lists every preset with its description", "[cli][style]") {
    const RunResult r = facet_shipped("styles");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const std::vector<std::string> lines = lines_of(r.output);
    int presets = 0;
    for (const auto& entry : fs::directory_iterator(facet::test::styles_dir())) {
        if (entry.path().extension() != ".yaml") continue;
        ++presets;
        const std::string name = entry.path().stem().string();
        const facet::StyleDesc style =
            facet::load_style_file(entry.path().string(), {facet::test::styles_dir()});
        const std::string line = listed_line(lines, name);
        INFO("preset " << name);
        REQUIRE_FALSE(line.empty());
        REQUIRE_FALSE(style.description.empty());
        CHECK_THAT(line, Contains(style.description));
        CHECK_THAT(line, !Contains("error"));
        if (!style.chain.empty())
            CHECK_THAT(line, Contains("(extends " + style.chain.back() + ")"));
    }
    CHECK(presets >= 19);
    CHECK(static_cast<int>(lines.size()) == presets);  // one line each, nothing else
    CHECK_THAT(listed_line(lines, "toon-outline"), Contains("(extends toon)"));
}

TEST_CASE("facet styles also lists presets on FACET_STYLE_PATH", "[cli][style]") {
    TempDir dir("cli-styles");
    write_text(dir.file("mine/sketchy.yaml"), "description: my sketchy look\nextends: toon\n");
    write_text(dir.file("mine/broken.yaml"), "description: broken\nshading: cartoon\n");
    const RunResult r = run_shell("FACET_STYLE_PATH=" + quoted(dir.file("mine")) + " " +
                                  quoted(facet::test::facet_executable()) + " styles");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const std::vector<std::string> lines = lines_of(r.output);
    CHECK_THAT(listed_line(lines, "sketchy"), Contains("my sketchy look (extends toon)"));
    // A broken preset is listed with its error rather than hiding the rest.
    CHECK_THAT(listed_line(lines, "broken"), Contains("cartoon"));
    CHECK_FALSE(listed_line(lines, "phong").empty());
}

TEST_CASE("facet sheet --styles writes one labelled cell per preset", "[cli][style]") {
    TempDir dir("cli-sheet");
    const std::string scene = write_text(dir.file("s.yaml"), kSheetScene);
    const std::string out = dir.file("sheets/two.png");
    const RunResult r =
        facet_shipped("sheet " + quoted(scene) + " --styles flat,toon --cell 80x60 -o " +
                      quoted(out) + " --threads 2");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    REQUIRE(fs::exists(out));
    const facet::DecodedPng png = facet::read_png(out);
    // Two cells side by side (about square: 2 columns), each with its label below.
    CHECK(png.width == 2 * 80);
    CHECK(png.height == 60 + label_band());
    // The cells hold different renders; the label band has the sheet's
    // light grey and some dark label text.
    CHECK(cell_difference(png, 0, 0, 80, 0, 80, 60) > 2.0);
    int dark = 0, light = 0;
    for (int y = 60; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x) {
            const int v = png.samples[(static_cast<size_t>(y) * png.width + x) * png.channels];
            dark += v < 64;
            light += v > 200;
        }
    CHECK(dark > 20);
    CHECK(light > png.width * (png.height - 60) / 2);
}

TEST_CASE("facet sheet: a label too long for its cell stays inside it", "[cli][style]") {
    // "wireframe-shaded" at the labels' size is about twice 80 pixels: it
    // is drawn smaller, then cut, and never reaches the next cell.
    TempDir dir("cli-sheet");
    const std::string scene = write_text(dir.file("s.yaml"), kSheetScene);
    const std::string out = dir.file("long.png");
    const RunResult r = facet_shipped("sheet " + quoted(scene) +
                                      " --styles wireframe-shaded,flat --cell 80x60 -o " +
                                      quoted(out) + " --threads 2");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const facet::DecodedPng png = facet::read_png(out);
    REQUIRE(png.width == 2 * 80);
    int dark_inside = 0, dark_at_border = 0;
    for (int y = 60; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x) {
            const bool dark =
                png.samples[(static_cast<size_t>(y) * png.width + x) * png.channels] < 64;
            if (dark && x < 74) ++dark_inside;
            if (dark && x >= 76 && x < 84) ++dark_at_border;
        }
    CHECK(dark_inside > 20);  // the label is there
    CHECK(dark_at_border == 0);
}

TEST_CASE("facet sheet --vary renders one cell per value", "[cli][style]") {
    TempDir dir("cli-sheet");
    const std::string scene = write_text(dir.file("s.yaml"), kSheetScene);
    const std::string row = dir.file("row.png"), grid = dir.file("grid.png");

    RunResult r =
        facet_shipped("sheet " + quoted(scene) +
                      " --vary style.cels=2,4,6 --cell 64x48 --columns 3 -o " + quoted(row));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("3 cells"));
    facet::DecodedPng png = facet::read_png(row);
    CHECK(png.width == 3 * 64);
    CHECK(png.height == 48 + label_band());
    // Each number of cels gives a different picture (mean difference in
    // 8-bit levels; identical cells give 0). With the seed's c' = c·q the
    // bright cels of 2 and 4 differ less than with keep_hue.
    CHECK(cell_difference(png, 0, 0, 64, 0, 64, 48) > 0.3);
    CHECK(cell_difference(png, 64, 0, 128, 0, 64, 48) > 0.3);

    // Without --columns, three cells make a 2 x 2 grid.
    r = facet_shipped("sheet " + quoted(scene) + " --vary style.cels=2,4,6 --cell 64x48 -o " +
                      quoted(grid));
    REQUIRE(r.exit_code == 0);
    png = facet::read_png(grid);
    CHECK(png.width == 2 * 64);
    CHECK(png.height == 2 * (48 + label_band()));

    // Styles and values together: one cell per pair.
    r = facet_shipped("sheet " + quoted(scene) +
                      " --styles palette,toon --vary style.cels=2,5 --cell 32x24 --columns 4 -o " +
                      quoted(grid));
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("4 cells"));
    png = facet::read_png(grid);
    CHECK(png.width == 4 * 32);
    CHECK(png.height == 24 + label_band());
}

TEST_CASE("facet sheet cells keep the scene's aspect ratio unless given both sides",
          "[cli][style]") {
    TempDir dir("cli-sheet");
    // A 16:9 scene: 4:3 cells would crop its sides.
    std::string text = kSheetScene;
    text.replace(text.find("[64, 48]"), 8, "[160, 90]");
    const std::string scene = write_text(dir.file("s.yaml"), text);
    const std::string out = dir.file("sheet.png");
    struct Case {
        const char* args;
        int cell_width, cell_height;
    };
    for (const Case& c :
         {Case{"", 320, 180}, Case{"--cell 100", 100, 56}, Case{"--cell 80x80", 80, 80}}) {
        INFO(c.args);
        const RunResult r = facet_shipped("sheet " + quoted(scene) + " --styles flat " + c.args +
                                          " -o " + quoted(out) + " --threads 2");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const facet::DecodedPng png = facet::read_png(out);
        CHECK(png.width == c.cell_width);
        CHECK(png.height == c.cell_height + label_band());
    }
}

TEST_CASE("facet sheet errors exit with code 2 and write nothing", "[cli][style]") {
    TempDir dir("cli-sheet");
    const std::string scene = write_text(dir.file("s.yaml"), kSheetScene);
    const std::string out = dir.file("out/sheet.png");
    struct Case {
        const char* name;
        std::string args;
        std::string says;
    };
    const std::vector<Case> cases = {
        {"vary without '='", "--vary style.cels", "--vary style.cels"},
        {"vary without a key", "--vary =2,3", "expected key.path=v1,v2"},
        {"vary without values", "--vary style.cels=", "expected key.path=v1,v2"},
        {"vary with a bad value after a good one", "--vary style.cels=2,x", "--vary style.cels=x"},
        {"vary with an unknown key", "--vary style.cells=2,3", "did you mean 'cels'"},
        {"an unknown style", "--styles flat,nosuch", "no style preset named 'nosuch'"},
        {"neither --styles nor --vary", "", "--styles"},
        // --size, as for every command (--cell is an alias).
        {"a bad cell size", "--styles flat --size 64by48", "--size: expected WIDTHxHEIGHT"},
        {"a cell width of zero", "--styles flat --cell 0", "WIDTHxHEIGHT or WIDTH"},
        {"a frame outside the scene", "--styles flat -f 400", "outside the scene's frames"},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            const RunResult r =
                facet_shipped("sheet " + quoted(scene) + " " + c.args + " -o " + quoted(out));
            INFO(r.output);
            CHECK(r.exit_code == 2);
            CHECK_THAT(r.output, Contains(c.says));
            CHECK_FALSE(fs::exists(out));
            CHECK_FALSE(fs::exists(dir.file("out")));
        }
    }
}

TEST_CASE("a bad -D style value names the command line in validate and render", "[cli][style]") {
    TempDir dir("cli-style-define");
    const std::string scene = write_text(dir.file("s.yaml"), kSheetScene);
    RunResult r = facet_shipped("validate " + quoted(scene) + " -D style.cels=x");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("command line -D style.cels=x"));
    CHECK_THAT(r.output, Contains("'style.cels'"));

    r = facet_shipped("render " + quoted(scene) + " -D style.cels=99 --out " +
                      quoted(dir.file("out")));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("command line -D style.cels=99"));
    CHECK_THAT(r.output, Contains("between 0 and 64"));
    CHECK_FALSE(fs::exists(dir.file("out")));

    r = facet_shipped("validate " + quoted(scene) + " -D style.cels=3 --style toon");
    CHECK(r.exit_code == 0);
}
