// Output passes: the depth EXR holds linear view depth with +inf background,
// the depth PNG follows its documented mapping, and EXR colour is linear.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "output/encoders.hpp"
#include "support.hpp"

using namespace facet;

namespace {

// A unit cube at the origin seen straight on from z = 5: its front face is
// at z = 0.5, so the view depth there is exactly 4.5.
const char* kScene = R"(
output: { size: [64, 48], frames: "1", passes: [color, depth], formats: [png, exr],
          background: [0, 0, 0, 0], depth_range: [4, 5] }
style: unlit
camera: { position: [0, 0, 5], target: [0, 0, 0], fov: 30, near: 0.5, far: 50 }
objects:
  - { name: cube, primitive: { type: cube, size: 1 }, material: { color: [0.5, 0.25, 1] } }
)";

}  // namespace

TEST_CASE("depth and colour passes hold what the docs say", "[output]") {
    test::TempDir dir("outputs");
    std::string scene = test::write_text(dir.file("cube.yaml"), kScene);
    auto run = test::run_facet("render '" + scene + "' --out '" + dir.file("out") + "' --quiet");
    REQUIRE(run.exit_code == 0);
    const std::string base = dir.file("out/cube/");

    DecodedExr depth = read_exr(base + "depth.0001.exr");
    REQUIRE(depth.channel_names == std::vector<std::string>{"Z"});
    REQUIRE(depth.width == 64);
    const auto& z = depth.channels[0];
    CHECK(z[24 * 64 + 32] == Approx(4.5f).epsilon(1e-5));  // centre: the front face
    CHECK(std::isinf(z[0]));                               // corner: background

    // 16-bit PNG: depth_range [4, 5] maps 4 -> 65535 and 5 -> 0, so 4.5 -> half.
    DecodedPng depth_png = read_png(base + "depth.0001.png");
    REQUIRE(depth_png.bit_depth == 16);
    REQUIRE(depth_png.channels == 1);
    CHECK(std::abs(int(depth_png.samples[24 * 64 + 32]) - 32768) <= 2);
    CHECK(depth_png.samples[0] == 0);

    // EXR colour is linear: the material colour comes back unchanged (to
    // half precision); the transparent background keeps alpha 0.
    DecodedExr color = read_exr(base + "color.0001.exr");
    REQUIRE(color.channel_names.size() == 4);  // A, B, G, R (sorted by name)
    auto channel = [&](const std::string& name) {
        for (size_t i = 0; i < color.channel_names.size(); ++i)
            if (color.channel_names[i] == name) return color.channels[i];
        FAIL("no channel " << name);
        return std::vector<float>{};
    };
    CHECK(channel("R")[24 * 64 + 32] == Approx(0.5f).margin(1e-3));
    CHECK(channel("G")[24 * 64 + 32] == Approx(0.25f).margin(1e-3));
    CHECK(channel("B")[24 * 64 + 32] == Approx(1.0f).margin(1e-3));
    CHECK(channel("A")[0] == 0.0f);

    // The PNG is sRGB-encoded, and RGBA because the background is transparent:
    // linear 0.5 -> 188, 0.25 -> 137.
    DecodedPng png = read_png(base + "color.0001.png");
    REQUIRE(png.channels == 4);
    const size_t centre = (24 * 64 + 32) * 4;
    CHECK(png.samples[centre] == 188);
    CHECK(png.samples[centre + 1] == 137);
    CHECK(png.samples[centre + 2] == 255);
    CHECK(png.samples[3] == 0);
}
