// Ambient occlusion (style `occlusion`): corners and contacts darken, open
// faces keep their colour, and the result is the same for any thread count.
#include <catch2/catch.hpp>

#include <string>

#include <glm/mat4x4.hpp>

#include "core/half.hpp"
#include "render_check.hpp"
#include "support.hpp"

namespace {

// A white floor and a wall standing on it across z = -1 (its front face at
// z = -0.9), unlit, seen from the front and above.
// `output` adds keys to the output block: passes, another background.
facet::FrameImages render_corner(const std::string& occlusion, unsigned threads,
                                 const std::string& output = "background: [0, 0, 0, 1]",
                                 const std::string& floor_size = "8") {
    facet::test::TempDir dir("occlusion");
    const std::string text = R"(output: { size: [240, 160], samples: 4, )" + output + R"( }
camera: { position: [0, 2.2, 4], target: [0, 0.2, -0.5], fov: 40 }
style: { shading: unlit, occlusion: )" +
                             occlusion +
                             R"( }
objects:
  - name: floor
    primitive: { type: plane, size: )" +
                             floor_size + R"( }
    material: { color: [0.8, 0.8, 0.8] }
  - name: wall
    primitive: { type: cube, size: 1 }
    scale: [4, 2, 0.2]
    translate: [0, 1, -1]
    material: { color: [0.8, 0.8, 0.8] }
)";
    return facet::test::render_yaml(dir.path(), text, 1, threads);
}

// The red value of the pixel that shows world point p.
float value_at(const facet::FrameImages& images, glm::vec3 p) {
    return facet::test::pixel_at(images, images.color, p).r;
}

// The mean absolute difference of two renders' red channels.
double mean_red_difference(const facet::FrameImages& one, const facet::FrameImages& other) {
    const auto a = facet::to_float_image(one.color).pixels;
    const auto b = facet::to_float_image(other.color).pixels;
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i].r - b[i].r);
    return sum / static_cast<double>(a.size());
}

}  // namespace

TEST_CASE("occlusion darkens the corner where a wall meets the floor, not open faces",
          "[render][occlusion]") {
    const facet::FrameImages plain = render_corner("false", 2);
    // Per pixel: the model itself (half resolution is compared with it below).
    const facet::FrameImages occluded = render_corner("{ radius: 0.5, resolution: full }", 2);
    const glm::vec3 corner(0.3f, 0.0f, -0.85f);    // floor, 5 cm in front of the wall
    const glm::vec3 open_floor(0.3f, 0.0f, 1.2f);  // floor, 2 m in front of it
    const glm::vec3 open_wall(0.3f, 1.6f, -0.9f);  // the wall's face, 1.6 m up
    REQUIRE(value_at(plain, corner) == Approx(0.8f).margin(0.01));
    CHECK(value_at(occluded, corner) < 0.8f * value_at(plain, corner));
    CHECK(value_at(occluded, open_floor) == Approx(value_at(plain, open_floor)).margin(0.01));
    CHECK(value_at(occluded, open_wall) == Approx(value_at(plain, open_wall)).margin(0.01));
    // Darker the nearer the corner.
    CHECK(value_at(occluded, corner) < value_at(occluded, {0.3f, 0.0f, -0.6f}));
    // Strength scales it: none at 0.
    const facet::FrameImages none = render_corner("{ radius: 0.5, strength: 0 }", 2);
    CHECK(facet::to_float_image(none.color).pixels == facet::to_float_image(plain.color).pixels);
}

TEST_CASE("occlusion is the same for any thread count", "[render][occlusion]") {
    const facet::FrameImages one = render_corner("{ radius: 0.5 }", 1);
    const facet::FrameImages three = render_corner("{ radius: 0.5 }", 3);
    CHECK(facet::to_float_image(one.color).pixels == facet::to_float_image(three.color).pixels);
}

// Half resolution (the default) finds the occlusion once per 2 x 2 pixels:
// it darkens the same corner about as much as `resolution: full`, keeps
// open faces open, and stays the same for any thread count.
TEST_CASE("occlusion at half resolution matches full resolution", "[render][occlusion]") {
    const facet::FrameImages full = render_corner("{ radius: 0.5, resolution: full }", 2);
    const facet::FrameImages half = render_corner("{ radius: 0.5, resolution: half }", 2);
    const facet::FrameImages by_default = render_corner("{ radius: 0.5 }", 2);
    CHECK(facet::to_float_image(by_default.color).pixels ==
          facet::to_float_image(half.color).pixels);
    CHECK(facet::to_float_image(full.color).pixels != facet::to_float_image(half.color).pixels);
    for (const glm::vec3 p : {glm::vec3(0.3f, 0.0f, -0.85f), glm::vec3(0.3f, 0.0f, -0.6f),
                              glm::vec3(-1.0f, 0.0f, -0.8f), glm::vec3(0.3f, 0.0f, 1.2f),
                              glm::vec3(0.3f, 1.6f, -0.9f)}) {
        INFO("at " << p.x << ", " << p.y << ", " << p.z);
        // Half resolution takes a cell's value up to a pixel away: in the
        // corner, where occlusion changes fastest, that is about 0.03.
        CHECK(value_at(half, p) == Approx(value_at(full, p)).margin(0.035));
    }
    // Across the frame, the two differ little on average.
    CHECK(mean_red_difference(full, half) < 0.004);
    const facet::FrameImages three = render_corner("{ radius: 0.5, resolution: half }", 3);
    CHECK(facet::to_float_image(three.color).pixels == facet::to_float_image(half.color).pixels);
}

TEST_CASE("occlusion resolution other than half or full is refused", "[render][occlusion]") {
    CHECK_THROWS_WITH(render_corner("{ radius: 0.5, resolution: quarter }", 1),
                      Catch::Matchers::Contains("resolution") && Catch::Matchers::Contains("half"));
}

// Alone, occlusion runs on the resolved pixels (render/occlusion_stage.hpp);
// beside the lines pass it runs on every sample. The two agree, and on the
// pixels it darkens only the share of a pixel that shows a surface.
TEST_CASE("occlusion on the pixels matches occlusion on the samples", "[render][occlusion]") {
    // A coloured background: the share of an edge pixel it shows stays as it is.
    const std::string occlusion = "{ radius: 0.5 }", background = "background: [0.2, 0.4, 0.6, 1]";
    const facet::FrameImages on_pixels = render_corner(occlusion, 2, background);
    const facet::FrameImages on_samples =
        render_corner(occlusion, 2, background + ", passes: [color, lines]");
    for (const glm::vec3 p : {glm::vec3(0.3f, 0.0f, -0.85f), glm::vec3(0.3f, 0.0f, -0.6f),
                              glm::vec3(-1.0f, 0.0f, -0.8f), glm::vec3(0.3f, 0.0f, 1.2f)}) {
        INFO("at " << p.x << ", " << p.y << ", " << p.z);
        CHECK(value_at(on_pixels, p) == Approx(value_at(on_samples, p)).margin(0.01));
    }
    CHECK(mean_red_difference(on_pixels, on_samples) < 0.002);
}

TEST_CASE("occlusion on the pixels leaves a transparent background's share alone",
          "[render][occlusion]") {
    // A see-through background, and a floor 2 m wide under the 4 m wall:
    // the corner's ends, and the floor's sides, meet the background in
    // pixels that are part surface, part background.
    const std::string output = "background: [0.2, 0.4, 0.6, 0], passes: [color, alpha]";
    const facet::FrameImages plain = render_corner("false", 2, output, "2");
    const facet::FrameImages occluded = render_corner("{ radius: 0.5 }", 2, output, "2");
    const auto plain_color = facet::to_float_image(plain.color).pixels;
    const auto color = facet::to_float_image(occluded.color).pixels;
    const auto plain_alpha = facet::to_float_image(plain.alpha).pixels;
    const auto alpha = facet::to_float_image(occluded.alpha).pixels;
    size_t edge_pixels = 0;
    for (size_t i = 0; i < color.size(); ++i) {
        // Opaque surfaces hide as much of the background with occlusion as without.
        REQUIRE(color[i].a == plain_color[i].a);
        REQUIRE(alpha[i].a == plain_alpha[i].a);
        if (plain_alpha[i].a > 0.0f && plain_alpha[i].a < 1.0f) ++edge_pixels;
        // Nothing gets lighter; the background alone stays as it was.
        CHECK(color[i].r <= plain_color[i].r);
        if (plain_alpha[i].a == 0.0f) CHECK(color[i] == plain_color[i]);
    }
    CHECK(edge_pixels > 20);
    // The corner darkens in both passes.
    const glm::vec3 corner(0.3f, 0.0f, -0.85f);
    CHECK(facet::test::pixel_at(occluded, occluded.alpha, corner).r <
          0.9f * facet::test::pixel_at(plain, plain.alpha, corner).r);
    CHECK(value_at(occluded, corner) < 0.9f * value_at(plain, corner));
}

TEST_CASE("occlusion on an image narrower than its cells leaves it open", "[render][occlusion]") {
    for (const char* size : {"[1, 9]", "[9, 1]", "[1, 1]"}) {
        INFO("size " << size);
        facet::test::TempDir dir("occlusion-tiny");
        const auto scene = [&](const std::string& occlusion) {
            return std::string("output: { size: ") + size +
                   R"(, samples: 4 }
camera: { position: [0, 2.2, 4], target: [0, 0, 0], fov: 40 }
style: { shading: unlit, occlusion: )" +
                   occlusion + R"( }
objects:
  - { primitive: { type: plane, size: 8 }, material: { color: [0.8, 0.8, 0.8] } }
)";
        };
        const facet::FrameImages plain = facet::test::render_yaml(dir.path(), scene("false"));
        const facet::FrameImages occluded = facet::test::render_yaml(dir.path(), scene("true"));
        CHECK(facet::to_float_image(occluded.color).pixels ==
              facet::to_float_image(plain.color).pixels);
    }
}
