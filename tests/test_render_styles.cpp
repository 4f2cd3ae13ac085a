// One reviewed reference render per shipped style preset: the shapes scene
// at 200x150 (tests/scenes/style_shapes.yaml), frame 1, with --style NAME.
// Thresholds as in test_render.cpp (render_check.hpp). New baselines:
// FACET_UPDATE_BASELINES=1, then look at every image before keeping it.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "render_check.hpp"
#include "scene/scene_desc.hpp"
#include "support.hpp"

using facet::test::check_render;

namespace {
constexpr const char* kScene = "tests/scenes/style_shapes.yaml";
// The presets that have a case below; kept in step with styles/ by the last test.
const std::set<std::string> kCovered = {
    "blinn-phong",      "blueprint", "clay",        "depth",         "flat",    "gooch",
    "gouraud",          "hatching",  "ink",         "intersections", "normals", "palette",
    "pencil",           "phong",     "toon",        "toon-outline",  "unlit",   "wireframe",
    "wireframe-shaded", "lit",       "lit-shadows", "palette-seed",  "pbr",
};
}  // namespace

// clang-format off
TEST_CASE("render style: blinn-phong",       "[render][style]") { check_render({kScene, 1, "style_blinn-phong.png", {}, {}, "blinn-phong"}); }
TEST_CASE("render style: blueprint",         "[render][style]") { check_render({kScene, 1, "style_blueprint.png", {}, {}, "blueprint"}); }
TEST_CASE("render style: clay",              "[render][style]") { check_render({kScene, 1, "style_clay.png", {}, {}, "clay"}); }
TEST_CASE("render style: depth",             "[render][style]") { check_render({kScene, 1, "style_depth.png", {}, {}, "depth"}); }
TEST_CASE("render style: flat",              "[render][style]") { check_render({kScene, 1, "style_flat.png", {}, {}, "flat"}); }
TEST_CASE("render style: gooch",             "[render][style]") { check_render({kScene, 1, "style_gooch.png", {}, {}, "gooch"}); }
TEST_CASE("render style: gouraud",           "[render][style]") { check_render({kScene, 1, "style_gouraud.png", {}, {}, "gouraud"}); }
TEST_CASE("render style: hatching",          "[render][style]") { check_render({kScene, 1, "style_hatching.png", {}, {}, "hatching"}); }
TEST_CASE("render style: ink",               "[render][style]") { check_render({kScene, 1, "style_ink.png", {}, {}, "ink"}); }
// The sphere sunk past its middle into the floor (its waterline on the
// upper half shows): the others rest on the floor and get no line.
TEST_CASE("render style: intersections",     "[render][style]") { check_render({kScene, 1, "style_intersections.png", {}, {"objects.0.translate=[0, -0.1, 0]"}, "intersections"}); }
TEST_CASE("render style: normals",           "[render][style]") { check_render({kScene, 1, "style_normals.png", {}, {}, "normals"}); }
TEST_CASE("render style: palette",           "[render][style]") { check_render({kScene, 1, "style_palette.png", {}, {}, "palette"}); }
TEST_CASE("render style: palette-seed",      "[render][style]") { check_render({kScene, 1, "style_palette-seed.png", {}, {}, "palette-seed"}); }
TEST_CASE("render style: pencil",            "[render][style]") { check_render({kScene, 1, "style_pencil.png", {}, {}, "pencil"}); }
TEST_CASE("render style: phong",             "[render][style]") { check_render({kScene, 1, "style_phong.png", {}, {}, "phong"}); }
TEST_CASE("render style: toon",              "[render][style]") { check_render({kScene, 1, "style_toon.png", {}, {}, "toon"}); }
TEST_CASE("render style: toon-outline",      "[render][style]") { check_render({kScene, 1, "style_toon-outline.png", {}, {}, "toon-outline"}); }
TEST_CASE("render style: unlit",             "[render][style]") { check_render({kScene, 1, "style_unlit.png", {}, {}, "unlit"}); }
TEST_CASE("render style: wireframe",         "[render][style]") { check_render({kScene, 1, "style_wireframe.png", {}, {}, "wireframe"}); }
TEST_CASE("render style: wireframe-shaded",  "[render][style]") { check_render({kScene, 1, "style_wireframe-shaded.png", {}, {}, "wireframe-shaded"}); }
TEST_CASE("render style: lit",               "[render][style]") { check_render({kScene, 1, "style_lit.png", {}, {}, "lit"}); }
TEST_CASE("render style: lit-shadows",       "[render][style]") { check_render({kScene, 1, "style_lit-shadows.png", {}, {}, "lit-shadows"}); }
TEST_CASE("render style: pbr",               "[render][style]") { check_render({kScene, 1, "style_pbr.png", {}, {}, "pbr"}); }
// clang-format on

TEST_CASE("every shipped preset has a reference render above", "[render][style]") {
    std::set<std::string> shipped;
    for (const auto& entry : std::filesystem::directory_iterator(facet::test::styles_dir()))
        if (entry.path().extension() == ".yaml") shipped.insert(entry.path().stem().string());
    CHECK(shipped == kCovered);
    for (const std::string& name : kCovered)
        CHECK(std::filesystem::exists(std::string(facet::test::baselines_dir()) + "/style_" + name +
                                      ".png"));
}

namespace {

// A cube seen from above one corner, unlit white faces and black 2-pixel
// feature edges; `hidden` is the wireframe's `hidden:` value, the hidden
// edges in red. Returns the number of red pixels.
const char* kWireCube = R"(output: { size: [120, 90], background: [1, 1, 1, 1] }
camera: { position: [2.2, 2.0, 2.6], target: [0, 0, 0], fov: 40 }
objects:
  - primitive: cube
style:
  shading: unlit
  wireframe:
    width: 2
    color: [0, 0, 0]
    fill: color
    fill_color: [1, 1, 1]
    hidden_color: [1, 0, 0]
)";

facet::ColorImage cube_wireframe(bool hidden) {
    facet::test::TempDir dir("wire-hidden");
    const std::string text =
        std::string(kWireCube) + "    hidden: " + (hidden ? "true" : "false") + "\n";
    return facet::to_float_image(facet::test::render_yaml(dir.path(), text, 1, 1).color);
}

bool is_black(const glm::vec4& c) {
    return c.r < 0.2f && c.g < 0.2f && c.b < 0.2f;
}

int red_pixels_of_cube_wireframe(bool hidden) {
    int red = 0, black = 0;
    for (const glm::vec4& c : cube_wireframe(hidden).pixels) {
        red += c.r > 0.5f && c.g < 0.3f && c.b < 0.3f;
        black += is_black(c);
    }
    CHECK(black > 100);  // the visible edges are there either way
    return red;
}

}  // namespace

// docs/styles.md and the issue: "Wireframe: visible edges only (hidden
// lines removed) and all edges". `hidden: true` must add the three edges
// behind the cube, in `hidden_color`.
TEST_CASE("wireframe hidden: true also draws the edges behind the surfaces", "[render][style]") {
    CHECK(red_pixels_of_cube_wireframe(false) == 0);
    CHECK(red_pixels_of_cube_wireframe(true) > 60);
}

namespace {

// A dense sphere (128 x 64 segments, 16 k triangles) filling the middle of
// a 160 x 160 image, white faces and black lines, with the silhouette
// outline the shipped wireframe presets have (the wireframe alone draws
// only the inner half of a contour edge, and at a smooth contour the
// triangles along it are edge-on); the counts of line pixels inside 80%
// of its radius and on its rim.
struct SphereLines {
    int inside = 0, rim = 0;
};

SphereLines wire_sphere_lines(const std::string& edges) {
    facet::test::TempDir dir("wire-sphere");
    const std::string text = R"(output: { size: [160, 160], background: [1, 1, 1, 1] }
camera: { position: [0.3, 0.8, 4], target: [0, 0, 0], fov: 40 }
objects:
  - primitive: { type: sphere, radius: 1, segments: 128, rings: 64 }
style:
  shading: unlit
  outlines: { silhouette: { width: 1.5, color: [0, 0, 0] } }
  wireframe: { width: 1.5, color: [0, 0, 0], fill: color, fill_color: [1, 1, 1], edges: )" +
                             edges + " }\n";
    const facet::ColorImage image =
        facet::to_float_image(facet::test::render_yaml(dir.path(), text).color);
    // The sphere's radius on screen: focal length times 1 / distance.
    const float distance = std::sqrt(0.3f * 0.3f + 0.8f * 0.8f + 4.0f * 4.0f);
    const float focal = 80.0f / std::tan(glm::radians(20.0f));
    const float radius = focal * std::tan(std::asin(1.0f / distance));
    SphereLines lines;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float r = std::hypot(x + 0.5f - 80.0f, y + 0.5f - 80.0f);
            const bool line = image.at(x, y).r < 0.6f;
            if (r < 0.8f * radius) lines.inside += line;
            if (std::abs(r - radius) < 1.5f) lines.rim += line;
        }
    return lines;
}

}  // namespace

// Wireframe draws what an illustrator draws: on a smooth dense mesh, the
// silhouette only, not a moiré of every triangle edge.
TEST_CASE("wireframe on a dense sphere draws only its silhouette", "[render][style]") {
    const SphereLines features = wire_sphere_lines("features");
    CHECK(features.inside == 0);
    CHECK(features.rim > 150);  // most of the rim's circumference (about 330 pixels)
    const SphereLines all = wire_sphere_lines("all");
    CHECK(all.inside > 1000);  // `edges: all` keeps the full triangle wireframe
}

// Where a hidden edge meets a visible one (at the silhouette's corners),
// the visible line wins: every pixel the visible edges make black stays so.
TEST_CASE("wireframe hidden edges stay under the visible ones", "[render][style]") {
    const facet::ColorImage visible_only = cube_wireframe(false);
    const facet::ColorImage with_hidden = cube_wireframe(true);
    int black = 0, lost = 0;
    for (size_t i = 0; i < visible_only.pixels.size(); ++i) {
        if (!is_black(visible_only.pixels[i])) continue;
        ++black;
        lost += !is_black(with_hidden.pixels[i]);
    }
    CHECK(black > 100);
    CHECK(lost == 0);
}

namespace {

// Runs of line coverage along one row of a render with white faces and
// background: total coverage of each run, left to right. `ink` is the line
// colour's grey level (linear), so coverage = (1 - value) / (1 - ink).
std::vector<double> line_runs(const facet::ColorImage& image, int y, float ink) {
    std::vector<double> runs;
    bool inside = false;
    for (int x = 0; x < image.width; ++x) {
        const glm::vec4 c = image.at(x, y);
        const double a = (1.0 - (c.r + c.g + c.b) / 3.0) / (1.0 - ink);
        if (a > 0.02) {
            if (!inside) runs.push_back(0);
            runs.back() += a;
        }
        inside = a > 0.02;
    }
    return runs;
}

}  // namespace

// The wireframe preset's lines should be one width: the cube's contour (a
// silhouette, where the wireframe draws only the half inside the surface)
// as wide as the edge between two visible faces.
TEST_CASE("the wireframe preset draws contour and inner edges equally wide", "[render][style]") {
    facet::test::TempDir dir("wire-width");
    const std::string path = facet::test::write_text(
        dir.file("s.yaml"), R"(output: { size: [120, 90], background: [1, 1, 1, 1], samples: 4 }
style: wireframe
camera: { position: [2.2, 2.0, 2.6], target: [0, 0, 0], fov: 40 }
objects:
  - primitive: cube
)");
    facet::SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    const facet::SceneDesc scene = facet::load_scene(path, options);
    REQUIRE(scene.style.wireframe.enabled);
    const float width = scene.style.wireframe.width.value;
    const float ink = scene.style.wireframe.color.value.x;
    const facet::World world = facet::build_world(scene);
    facet::ThreadPool pool(1);
    facet::FrameRenderer renderer(scene, world, pool);
    facet::FrameImages images;
    renderer.render(1, 0, images);
    // Rows across the cube's lower half: left contour, the near vertical
    // edge, right contour. The contours are anti-aliased against the
    // background, so they are compared on average over the rows.
    double contour = 0;
    int rows = 0;
    for (int y = 46; y <= 60; y += 2, ++rows) {
        const std::vector<double> runs = line_runs(facet::to_float_image(images.color), y, ink);
        INFO("row " << y);
        REQUIRE(runs.size() == 3);
        CHECK(runs[1] == Approx(width).margin(0.15));  // the inner edge is right
        contour += (runs[0] + runs[2]) / 2;
    }
    contour /= rows;
    INFO("inner edges " << width << " px, contour on average " << contour << " px");
    CHECK(contour == Approx(width).margin(0.35 * width));
}
