// Mipmaps: each level is the box-filtered half of the one before, and
// trilinear sampling blends levels by the level of detail.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "assets/texture.hpp"
#include "shade/texture_lod.hpp"

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

// Shading finds eight lanes' texture coordinates and footprints at once
// (shade/texture_lod.hpp, UvTransform's lane form); each lane must get the
// bits the one-point forms give, so that a pixel looks the same in any lane.
TEST_CASE("texture lookups over eight lanes give each lane's own bits", "[texture][lod]") {
    std::mt19937 random(36);
    std::uniform_real_distribution<float> uv(-40.0f, 40.0f), weight(0.0f, 1.0f), step(-1.0f, 1.0f),
        step_size(-8.0f, -1.0f);  // steps of 1e-8 to 0.1 per pixel
    const facet::UvTransform tiling =
        facet::UvTransform::from_trs({0.25, -3.5}, 0.7, {6.6667, 0.125});
    size_t magnified = 0, minified = 0;
    for (int round = 0; round < 2000; ++round) {
        facet::UvLanes c;
        facet::FootprintLanes s;
        const float size = std::pow(10.0f, step_size(random));
        for (int i = 0; i < facet::simd::kLanes; ++i) {
            for (int k = 0; k < 3; ++k) c.u[k][i] = uv(random), c.v[k][i] = uv(random);
            s.b1[i] = weight(random), s.b2[i] = weight(random) * (1.0f - s.b1[i]);
            s.ddx1[i] = size * step(random), s.ddx2[i] = size * step(random);
            s.ddy1[i] = size * step(random), s.ddy2[i] = size * step(random);
        }
        facet::UvLanes tiled = c;
        for (int k = 0; k < 3; ++k) tiling.apply(tiled.u[k], tiled.v[k]);
        const glm::vec2 texels(256.0f, 64.0f);
        const facet::TextureLookupLanes lanes = facet::texture_lookups(tiled, s, texels);
        for (int i = 0; i < facet::simd::kLanes; ++i) {
            glm::vec2 corner[3];
            for (int k = 0; k < 3; ++k) {
                corner[k] = tiling.apply(glm::vec2(c.u[k][i], c.v[k][i]));
                REQUIRE(corner[k] == glm::vec2(tiled.u[k][i], tiled.v[k][i]));
            }
            facet::SurfaceSample one{};
            one.bary = {1.0f - s.b1[i] - s.b2[i], s.b1[i], s.b2[i]};
            one.ddx = {0.0f, s.ddx1[i], s.ddx2[i]};
            one.ddy = {0.0f, s.ddy1[i], s.ddy2[i]};
            const facet::TextureFootprint want =
                facet::texture_lookup(corner[0], corner[1], corner[2], one, texels);
            const facet::TextureFootprint got = lanes.at(i);
            REQUIRE(got.uv == want.uv);
            REQUIRE(got.major_axis == want.major_axis);
            REQUIRE(got.major == want.major);
            REQUIRE(got.minor == want.minor);
            (want.major <= 1.0f ? magnified : minified) += 1;
        }
    }
    CHECK(magnified > 100);
    CHECK(minified > 100);
}
