// Values above the half-float maximum (the reliability issue, item 3): a
// brighter input never gives a darker pixel. Colour is stored saturated at
// 65504, and every tone curve maps that (and infinity) to its white.
#include <catch2/catch.hpp>

#include <cmath>

#include "compare_support.hpp"
#include "output/encoders.hpp"
#include "support.hpp"
#include "turntable_support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

// A Radiance .hdr of one radiance everywhere (flat RGBE scanlines).
std::string write_uniform_hdr(const std::string& path, float radiance) {
    int exponent = 0;
    const float mantissa = std::frexp(radiance, &exponent);  // radiance = m * 2^e, m in [0.5, 1)
    const auto m = static_cast<uint8_t>(mantissa * 256.0f);
    const auto e = static_cast<uint8_t>(exponent + 128);
    std::string text = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n";
    for (int i = 0; i < 32; ++i) text += std::string{char(m), char(m), char(m), char(e)};
    return write_text(path, text);
}

// The 8-bit value of a PNG's pixel (x, y), channel c.
int png_value(const DecodedPng& png, int x, int y, int c) {
    return png.samples[(static_cast<size_t>(y) * png.width + x) * png.channels + c];
}

}  // namespace

TEST_CASE("a light far brighter than the half-float range shows white under a tone curve",
          "[display][render]") {
    TempDir dir("bright-light");
    write_text(dir.file("bright.yaml"), R"(
output: { size: [48, 48], frames: "1", passes: [color], formats: [png, exr], tonemap: aces }
camera: { position: [0, 0, 4] }
lights: [ { type: directional, direction: [0, 0, -1], intensity: 70000 } ]
objects: [ { primitive: { type: cube }, material: { color: [0.8, 0.8, 0.8] } } ]
)");
    for (const char* curve : {"aces", "filmic", "neutral", "agx"}) {
        INFO(curve);
        const RunResult r =
            run_facet("render " + shell_quote(dir.file("bright.yaml")) + " -o " +
                      shell_quote(dir.file(curve)) + " -D output.tonemap=" + curve + " -q");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const std::string base = dir.file(std::string(curve) + "/bright/color.0001");
        const DecodedPng png = read_png(base + ".png");
        for (int c = 0; c < 3; ++c) CHECK(png_value(png, 24, 24, c) == 255);
        // The EXR keeps the largest finite half, never infinity.
        const DecodedExr exr = read_exr(base + ".exr");
        const size_t centre = 24 * 48 + 24;
        for (const char* name : {"R", "G", "B"}) {
            const auto at = std::find(exr.channel_names.begin(), exr.channel_names.end(), name);
            REQUIRE(at != exr.channel_names.end());
            CHECK(exr.channels[static_cast<size_t>(at - exr.channel_names.begin())][centre] ==
                  65504.0f);
        }
    }
}

TEST_CASE("a model's turntable under an environment of 1e5 is white, not black",
          "[display][render][turntable]") {
    TempDir dir("bright-environment");
    write_binary_stl(dir.file("cube.stl"), box_triangles({-1, -1, -1}, {1, 1, 1}));
    write_uniform_hdr(dir.file("uniform.hdr"), 1e5f);
    const RunResult r = run_facet("render " + shell_quote(dir.file("cube.stl")) +
                                  " -f 1 --size 64x48 -o " + shell_quote(dir.file("out")) +
                                  " --environment " + shell_quote(dir.file("uniform.hdr")) + " -q");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const DecodedPng png = read_png(dir.file("out/cube/color.0001.png"));
    int darkest = 255;
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x)
            for (int c = 0; c < 3; ++c) darkest = std::min(darkest, png_value(png, x, y, c));
    // The model, its ground and the background: all past the curve's knee.
    CHECK(darkest >= 200);
}
