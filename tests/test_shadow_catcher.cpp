// Shadow catchers (material shadow_catcher: true): a floor that shows only
// the shadows cast on it, over whatever background, transparent elsewhere.
#include <catch2/catch.hpp>

#include <string>

#include <glm/mat4x4.hpp>

#include "core/half.hpp"
#include "render_check.hpp"
#include "support.hpp"

using facet::test::pixel_at;

namespace {

// A cube (its centre at `cube_y`, 0.5 above the floor by default) over a
// shadow-catching floor, lit straight down, so its shadow is the square
// under it; seen from the front and above. `extra_light` adds a line to
// the lights; `passes` are the output's.
facet::FrameImages render_catcher(const std::string& background, const std::string& style,
                                  unsigned threads = 2, const std::string& extra_light = "",
                                  float cube_y = 1.0f,
                                  const std::string& passes = "[color, alpha]") {
    facet::test::TempDir dir("shadow-catcher");
    const std::string text = "output: { size: [200, 150], samples: 4, passes: " + passes +
                             ", background: " + background + R"( }
camera: { position: [0, 4, 5], target: [0, 0, 0], fov: 40 }
style: )" + style + R"(
lights:
  - { type: directional, direction: [0, -1, 0], intensity: 1, shadows: true }
)" + extra_light +
                             R"(
objects:
  - name: floor
    primitive: { type: plane, size: 8 }
    material: { color: [0.8, 0.8, 0.8], shadow_catcher: true }
  - name: cube
    primitive: { type: cube, size: 1 }
    translate: [0, )" + std::to_string(cube_y) +
                             R"(, 0]
    material: { color: [0.9, 0.5, 0.2] }
)";
    return facet::test::render_yaml(dir.path(), text, 1, threads);
}

const glm::vec3 kInShadow(0.0f, 0.0f, 0.4f);  // under the cube, in front of it
const glm::vec3 kOpenFloor(2.5f, 0.0f, 0.8f);

}  // namespace

TEST_CASE("shadow catcher: transparent where unshadowed, dark where shadowed",
          "[render][shadow_catcher]") {
    const facet::FrameImages images = render_catcher("transparent", "phong");
    // Unshadowed: nothing at all, in the colour and the alpha pass.
    CHECK(pixel_at(images, images.color, kOpenFloor) == glm::vec4(0.0f));
    CHECK(pixel_at(images, images.alpha, kOpenFloor) == glm::vec4(0.0f));
    // In the shadow: black over nothing, covering most of the background
    // (all but the ambient term's share, 0.125 / 1.125).
    const glm::vec4 shadow = pixel_at(images, images.alpha, kInShadow);
    CHECK(shadow.a > 0.8f);
    CHECK(glm::vec3(shadow) == glm::vec3(0.0f));
    // The cube itself is there as usual.
    CHECK(pixel_at(images, images.color, {0.0f, 1.5f, 0.0f}).a == 1.0f);
}

TEST_CASE("shadow catcher: over a coloured background it shows the background, darkened",
          "[render][shadow_catcher]") {
    // A second light, casting no shadow, keeps half the lights' light in the
    // shadow, and the ambient term (ka 0.1 of the default white ambient,
    // over kd 0.8) stays whole: (0.125 + 1) / (0.125 + 2) of the background.
    const facet::FrameImages images = render_catcher(
        "[0.2, 0.4, 0.6]", "phong", 2, "  - { type: directional, direction: [0, -1, 0] }");
    const float kept = (0.125f + 1.0f) / (0.125f + 2.0f);
    const glm::vec4 open = pixel_at(images, images.color, kOpenFloor);
    for (int c = 0; c < 3; ++c)
        CHECK(open[c] == Approx(glm::vec3(0.2f, 0.4f, 0.6f)[c]).margin(1e-3));
    CHECK(open.a == 1.0f);
    const glm::vec4 dark = pixel_at(images, images.color, kInShadow);
    CHECK(dark.b == Approx(kept * 0.6f).margin(0.01));
    // Same hue: the background scaled down.
    CHECK(dark.r / dark.b == Approx(0.2f / 0.6f).margin(0.02));
}

TEST_CASE("shadow catcher: occlusion darkens it too, and threads do not matter",
          "[render][shadow_catcher]") {
    const std::string style = "{ shading: phong, occlusion: { radius: 1.0 } }";
    // The cube stands on the floor: its shadow is hidden under it.
    const facet::FrameImages one = render_catcher("transparent", style, 1, "", 0.5f);
    const facet::FrameImages three = render_catcher("transparent", style, 3, "", 0.5f);
    CHECK(facet::to_float_image(one.color).pixels == facet::to_float_image(three.color).pixels);
    CHECK(facet::to_float_image(one.alpha).pixels == facet::to_float_image(three.alpha).pixels);
    // Beside the cube's base, outside its shadow (the light is straight
    // down), occlusion alone makes the catcher cover a little.
    const glm::vec4 beside = pixel_at(one, one.alpha, {0.0f, 0.0f, 0.62f});
    INFO("alpha beside the base " << beside.a);
    CHECK(beside.a > 0.05f);
    CHECK(pixel_at(one, one.alpha, kOpenFloor).a == 0.0f);
}

// Occlusion alone runs on the resolved pixels, beside the lines pass on
// every sample (render/occlusion_stage.hpp): on a catcher, whose surface
// hides only part of the background, the two agree.
TEST_CASE("shadow catcher: occlusion on the pixels matches occlusion on the samples",
          "[render][shadow_catcher]") {
    const std::string style = "{ shading: phong, occlusion: { radius: 1.0 } }";
    for (const char* background : {"transparent", "[0.2, 0.4, 0.6]"}) {
        INFO("background " << background);
        const facet::FrameImages on_pixels = render_catcher(background, style, 2, "", 0.5f);
        const facet::FrameImages on_samples =
            render_catcher(background, style, 2, "", 0.5f, "[color, alpha, lines]");
        for (const glm::vec3 p :
             {glm::vec3(0.0f, 0.0f, 0.62f), glm::vec3(0.62f, 0.0f, 0.0f), kOpenFloor}) {
            INFO("at " << p.x << ", " << p.y << ", " << p.z);
            const glm::vec4 a = pixel_at(on_pixels, on_pixels.alpha, p);
            const glm::vec4 b = pixel_at(on_samples, on_samples.alpha, p);
            CHECK(a.a == Approx(b.a).margin(0.02));
            const glm::vec4 c = pixel_at(on_pixels, on_pixels.color, p);
            const glm::vec4 d = pixel_at(on_samples, on_samples.color, p);
            for (int k = 0; k < 4; ++k) CHECK(c[k] == Approx(d[k]).margin(0.02));
        }
    }
}
