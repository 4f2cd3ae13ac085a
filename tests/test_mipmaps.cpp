// Mipmaps: each level is the box-filtered half of the one before, and
// trilinear sampling blends levels by the level of detail.
#include <catch2/catch.hpp>

#include <vector>

#include "assets/texture.hpp"

using namespace facet;

namespace {

// A grey 8-bit checker of one-texel squares: linear values 0 and 1.
Texture fine_checker(int width, int height) {
    std::vector<uint8_t> bytes(static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) bytes[y * width + x] = (x + y) % 2 ? 255 : 0;
    return texture_from_pixels(width, height, 1, 8, bytes.data());
}

}  // namespace

TEST_CASE("the mip chain halves down to one texel", "[texture][mipmap]") {
    // Levels are kept as 8-bit sRGB like the image, so a mean of 0.5 comes
    // back as the nearest sRGB byte (188 -> 0.5029).
    constexpr float kStep = 0.004f;
    Texture t = fine_checker(256, 64);
    REQUIRE(t.level_count() == 9);  // 256x64, 128x32, 64x16, 32x8, 16x4, 8x2, 4x1, 2x1, 1x1
    CHECK(t.level(1).width == 128);
    CHECK(t.level(1).height == 32);
    CHECK(t.level(8).width == 1);
    CHECK(t.level(8).height == 1);
    // Every 2x2 block of the checker holds two black and two white texels.
    for (int l = 1; l < t.level_count(); ++l)
        for (int y = 0; y < t.level(l).height; ++y)
            for (int x = 0; x < t.level(l).width; ++x)
                CHECK(t.texel(l, x, y).r == Approx(0.5f).margin(kStep));

    Texture odd = fine_checker(5, 3);  // odd sizes round up: 3x2, 2x1, 1x1
    REQUIRE(odd.level_count() == 4);
    CHECK(odd.level(1).width == 3);
    CHECK(odd.level(1).height == 2);
    // Top-right texel of level 1 averages column 4 with itself over rows 0-1:
    // (x + y) odd -> white: (4,0) black, (4,1) white -> 0.5.
    CHECK(odd.texel(1, 2, 0).r == Approx(0.5f).margin(kStep));
    CHECK(t.bytes() == texture_bytes(256, 64, 8));
}

TEST_CASE("trilinear sampling picks and blends levels by lod", "[texture][mipmap]") {
    Texture t = fine_checker(64, 64);
    const glm::vec2 centre_of_texel_0(0.5f / 64, 0.5f / 64);  // texel (0, 0) is black
    CHECK(t.sample(centre_of_texel_0, 0.0f).r == Approx(0.0f).margin(1e-6));
    CHECK(t.sample(centre_of_texel_0, -3.0f).r == Approx(0.0f).margin(1e-6));
    // From level 1 on, everything is mid grey.
    CHECK(t.sample(centre_of_texel_0, 1.0f).r == Approx(0.5f).margin(0.004));
    CHECK(t.sample(centre_of_texel_0, 20.0f).r == Approx(0.5f).margin(0.004));
    // Half way between level 0 (black here) and level 1 (grey).
    CHECK(t.sample(centre_of_texel_0, 0.5f).r == Approx(0.25f).margin(0.002));
}
