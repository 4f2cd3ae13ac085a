// Floors that ground a model: a material that fades into the background
// (`fade: [start, end]`), and Gouraud surfaces whose shadows are looked up
// per pixel, so a floor of four vertices still shows a shadow.
#include <catch2/catch.hpp>

#include <string>

#include <glm/geometric.hpp>

#include "core/half.hpp"
#include "render_check.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using facet::test::pixel_at;

namespace {

// A cube floating 0.5 above a plane of `floor_size` (two triangles), lit
// straight down; seen from the front and above, over a blue background.
facet::FrameImages render_floor(const std::string& style, const std::string& floor_material,
                                float floor_size = 8, unsigned threads = 2) {
    facet::test::TempDir dir("floors");
    const std::string text =
        "output: { size: [200, 150], samples: 4, passes: [color, alpha], "
        "background: [0.1, 0.2, 0.6, 1] }\n"
        "camera: { position: [0, 4, 5], target: [0, 0, 0], fov: 40 }\n"
        "style: " +
        style +
        "\n"
        "lights:\n"
        "  - { type: directional, direction: [0, -1, 0], intensity: 1, shadows: true }\n"
        "objects:\n"
        "  - name: floor\n"
        "    primitive: { type: plane, size: " +
        std::to_string(floor_size) +
        " }\n"
        "    material: { color: [0.8, 0.8, 0.8], ambient: 0.25" +
        floor_material +
        " }\n"
        "  - name: cube\n"
        "    primitive: { type: cube, size: 1 }\n"
        "    translate: [0, 1, 0]\n"
        "    material: { color: [0.9, 0.5, 0.2] }\n";
    return facet::test::render_yaml(dir.path(), text, 1, threads);
}

const glm::vec3 kInShadow(0.0f, 0.0f, 0.4f);  // under the cube, in front of it
const glm::vec3 kOpenFloor(1.5f, 0.0f, 0.8f);
const glm::vec3 kBackground(0.1f, 0.2f, 0.6f);

}  // namespace

TEST_CASE("a fading floor keeps its colour near the middle and is the background past the end",
          "[render][floors]") {
    const facet::FrameImages plain = render_floor("phong", "");
    const facet::FrameImages faded = render_floor("phong", ", fade: [2, 3]");
    // Inside the start: untouched.
    CHECK(pixel_at(faded, faded.color, kOpenFloor) == pixel_at(plain, plain.color, kOpenFloor));
    // Past the end (3.5 m out): the background, and nothing in the alpha pass.
    const glm::vec3 far(-3.5f, 0.0f, -0.5f);
    const glm::vec4 gone = pixel_at(faded, faded.color, far);
    for (int a = 0; a < 3; ++a)
        CHECK(gone[a] == Approx(kBackground[a]).margin(1e-3));  // half floats
    CHECK(pixel_at(faded, faded.alpha, far) == glm::vec4(0.0f));
    // Halfway (2.5 m): between the two, its coverage a half.
    const glm::vec3 middle(-2.5f, 0.0f, 0.0f);
    const glm::vec4 half = pixel_at(faded, faded.alpha, middle);
    CHECK(half.a == Approx(0.5f).margin(0.08f));
    const glm::vec4 lit = pixel_at(plain, plain.color, middle);
    const glm::vec4 mixed = pixel_at(faded, faded.color, middle);
    CHECK(mixed.r == Approx(0.5f * (lit.r + kBackground.r)).margin(0.05f));
    // Threads do not matter.
    const facet::FrameImages three = render_floor("phong", ", fade: [2, 3]", 8, 3);
    CHECK(facet::to_float_image(three.color).pixels == facet::to_float_image(faded.color).pixels);
    CHECK(facet::to_float_image(three.alpha).pixels == facet::to_float_image(faded.alpha).pixels);
}

TEST_CASE("a fade that does not end after it starts is refused with its place",
          "[render][floors]") {
    facet::test::TempDir dir("floors-bad");
    const std::string text =
        "objects:\n  - primitive: { type: plane }\n"
        "    material: { fade: [3, 2] }\n";
    const std::string message =
        facet::test::load_error(facet::test::write_text(dir.file("scene.yaml"), text));
    CHECK_THAT(message, Catch::Contains("scene.yaml:3:"));
    CHECK_THAT(message, Catch::Contains("fade"));
    CHECK_THAT(message, Catch::Contains("start < end"));
}

TEST_CASE("Gouraud shows a shadow on a floor of four vertices, per pixel", "[render][floors]") {
    // The floor's corners are all in the light: a shadow sampled at the
    // vertices alone would leave the floor evenly lit.
    const facet::FrameImages g = render_floor("gouraud", "", 8);
    const float shadowed = pixel_at(g, g.color, kInShadow).r;
    const float open = pixel_at(g, g.color, kOpenFloor).r;
    INFO("shadowed " << shadowed << ", open " << open);
    CHECK(shadowed < 0.5f * open);
    // In the open the light is Gouraud's own, the same as without shadows.
    const facet::FrameImages unshadowed = render_floor("{ extends: gouraud, shadows: false }", "");
    CHECK(open == Approx(pixel_at(unshadowed, unshadowed.color, kOpenFloor).r).epsilon(1e-5));
    // And the shadow matches the per-pixel model's (Phong) within a few percent.
    const facet::FrameImages phong = render_floor("phong", "");
    CHECK(shadowed == Approx(pixel_at(phong, phong.color, kInShadow).r).margin(0.03f));
}
