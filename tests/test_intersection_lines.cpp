// Intersection lines (outlines.intersection) only where two surfaces
// really cross: never along a silhouette that passes close to another
// surface, such as a model's edge just above its floor.
#include <catch2/catch.hpp>

#include <string>

#include "core/half.hpp"
#include "render_check.hpp"
#include "support.hpp"

namespace {

// Unlit white faces on a grey floor, intersection lines in pure red, seen
// from a low camera so the cube's top and side edges stand against the
// floor not far behind them. `cube_y` is the height of the cube's centre
// (size 1): 0.5 rests on the floor, above floats, below sinks in.
struct RedLines {
    int pixels = 0;
    int first_row = 1 << 30, last_row = -1;    // of the red pixels
    int cube_top = 1 << 30, cube_bottom = -1;  // rows of the cube's white faces
};

RedLines red_lines(float cube_y) {
    facet::test::TempDir dir("intersection-lines");
    const std::string text = R"(output: { size: [200, 150], samples: 4, background: [0, 0, 0, 1] }
camera: { position: [0.8, 2.6, 4.2], target: [0, 0.3, 0], fov: 35 }
style:
  shading: unlit
  outlines: { intersection: { width: 2, color: [1, 0, 0] } }
objects:
  - name: floor
    primitive: { type: plane, size: 8 }
    material: { color: [0.5, 0.5, 0.5] }
  - name: cube
    primitive: { type: cube, size: 1 }
    rotate: [0, 30, 0]
    material: { color: [1, 1, 1] }
    translate: [0, )" + std::to_string(cube_y) +
                             ", 0]\n";
    const facet::ColorImage image =
        facet::to_float_image(facet::test::render_yaml(dir.path(), text).color);
    RedLines red;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 c = image.at(x, y);
            if (c.r > 0.6f && c.g < 0.35f && c.b < 0.35f) {
                ++red.pixels;
                red.first_row = std::min(red.first_row, y);
                red.last_row = std::max(red.last_row, y);
            }
            if (c.r > 0.9f && c.g > 0.9f && c.b > 0.9f) {
                red.cube_top = std::min(red.cube_top, y);
                red.cube_bottom = std::max(red.cube_bottom, y);
            }
        }
    return red;
}

}  // namespace

TEST_CASE("intersection lines: none along a silhouette just above a floor", "[render][outline]") {
    // 6 cm above the floor, about three pixels here: the cube's lower edges
    // pass within a few thousandths of the floor's depth, and nothing
    // crosses.
    CHECK(red_lines(0.56f).pixels == 0);
    CHECK(red_lines(0.9f).pixels == 0);
}

TEST_CASE("intersection lines: along the waterline of a cube sunk into the floor",
          "[render][outline]") {
    const RedLines sunk = red_lines(0.2f);
    CHECK(sunk.pixels > 100);  // the waterline round the cube's visible sides
    // Only low on the cube, never at its top edges against the floor.
    CHECK(sunk.first_row > (sunk.cube_top + sunk.cube_bottom) / 2);
}

TEST_CASE("intersection lines: none on a cube resting on the floor", "[render][outline]") {
    // Resting flush, the cube's base touches the floor but nothing passes
    // through it: no line at its lower edges (which the image alone cannot
    // tell from a waterline) nor anywhere on its silhouette.
    const RedLines resting = red_lines(0.5f);
    REQUIRE(resting.cube_bottom > resting.cube_top);  // the cube is in view
    CHECK(resting.pixels == 0);
    // Sunk by 2 mm, a fifth of a pixel here, it does pass through.
    CHECK(red_lines(0.498f).pixels > 100);
}
