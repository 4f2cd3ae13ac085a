// Texture decoding and sampling (src/assets/texture.cpp). PNGs are written
// here byte by byte (stored deflate blocks), so the expected texel values come
// from the bytes we chose, not from any encoder under test.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/texture.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

using facet::test::require_input_error;
using facet::test::TempDir;
using facet::test::write_bytes;

namespace {

// The sRGB transfer function (IEC 61966-2-1), in double precision.
double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
float srgb8(int byte) {
    return static_cast<float>(srgb_to_linear(byte / 255.0));
}

uint32_t crc32(const uint8_t* data, size_t n, uint32_t crc = 0) {
    crc = ~crc;
    for (size_t i = 0; i < n; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void put_be32(std::vector<uint8_t>& out, uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<uint8_t>(v >> s));
}

void chunk(std::vector<uint8_t>& png, const char* type, const std::vector<uint8_t>& data) {
    put_be32(png, static_cast<uint32_t>(data.size()));
    std::vector<uint8_t> body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    png.insert(png.end(), body.begin(), body.end());
    put_be32(png, crc32(body.data(), body.size()));
}

// A PNG with the given IHDR colour type and bit depth; `samples` are the
// unfiltered pixel bytes row after row (16-bit samples big-endian, as in PNG).
std::vector<uint8_t> make_png(int width, int height, int color_type, int bit_depth,
                              const std::vector<uint8_t>& samples) {
    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::vector<uint8_t> ihdr;
    put_be32(ihdr, static_cast<uint32_t>(width));
    put_be32(ihdr, static_cast<uint32_t>(height));
    ihdr.insert(ihdr.end(),
                {static_cast<uint8_t>(bit_depth), static_cast<uint8_t>(color_type), 0, 0, 0});
    chunk(png, "IHDR", ihdr);

    const size_t row = samples.size() / height;
    std::vector<uint8_t> raw;
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);  // filter: none
        raw.insert(raw.end(), samples.begin() + y * row, samples.begin() + (y + 1) * row);
    }
    std::vector<uint8_t> z = {0x78, 0x01};
    for (size_t at = 0; at < raw.size() || at == 0;) {
        size_t n = std::min<size_t>(65535, raw.size() - at);
        bool last = at + n == raw.size();
        z.push_back(last ? 1 : 0);
        z.insert(z.end(), {static_cast<uint8_t>(n), static_cast<uint8_t>(n >> 8),
                           static_cast<uint8_t>(~n), static_cast<uint8_t>(~n >> 8)});
        z.insert(z.end(), raw.begin() + at, raw.begin() + at + n);
        at += n;
        if (last) break;
    }
    uint32_t a = 1, b = 0;
    for (uint8_t byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    put_be32(z, (b << 16) | a);
    chunk(png, "IDAT", z);
    chunk(png, "IEND", {});
    return png;
}

// 16-bit images are kept as half floats: 11 significant bits, so values up
// to 1 come back within 2^-12 of what was decoded.
constexpr float kHalfStep = 1.0f / 4096;

void require_texel(const glm::vec4& got, const glm::vec4& want, float eps = 1e-5f) {
    INFO("got (" << got.r << ", " << got.g << ", " << got.b << ", " << got.a << ") want (" << want.r
                 << ", " << want.g << ", " << want.b << ", " << want.a << ")");
    for (int c = 0; c < 4; ++c) CHECK(got[c] == Approx(want[c]).margin(eps));
}

// A texture made directly from linear values, for sampling tests.
facet::Texture grey_row(const std::vector<float>& values, facet::Wrap wrap, bool vertical = false) {
    std::vector<glm::vec4> texels;
    for (float v : values) texels.push_back({v, v, v, 1});
    const int n = static_cast<int>(values.size());
    facet::Texture t = facet::Texture::from_linear(vertical ? 1 : n, vertical ? n : 1, texels,
                                                   facet::Texture::Format::half);
    t.sampler.wrap_s = t.sampler.wrap_t = wrap;
    return t;
}

// Level 0 as linear RGBA, row by row.
std::vector<glm::vec4> texels_of(const facet::Texture& t) {
    std::vector<glm::vec4> out;
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) out.push_back(t.texel(0, x, y));
    return out;
}

}  // namespace

TEST_CASE("sRGB bytes become linear values", "[assets][texture]") {
    // Reference points of the sRGB curve.
    CHECK(srgb8(128) == Approx(0.21586).epsilon(1e-4));
    CHECK(srgb8(10) == Approx(10 / 255.0 / 12.92).epsilon(1e-6));
    const std::vector<uint8_t> grey = {0, 10, 128, 255};
    facet::Texture t = facet::texture_from_pixels(4, 1, 1, 8, grey.data());
    REQUIRE(texels_of(t).size() == 4);
    require_texel(texels_of(t)[0], {0, 0, 0, 1});
    require_texel(texels_of(t)[1], glm::vec4(glm::vec3(srgb8(10)), 1), 1e-7f);
    require_texel(texels_of(t)[2], glm::vec4(glm::vec3(0.21586f), 1), 1e-4f);
    require_texel(texels_of(t)[3], {1, 1, 1, 1});
    // Every byte: monotonic, and matches the double-precision curve.
    std::vector<uint8_t> all(256);
    for (int i = 0; i < 256; ++i) all[i] = static_cast<uint8_t>(i);
    facet::Texture ramp = facet::texture_from_pixels(256, 1, 1, 8, all.data());
    for (int i = 0; i < 256; ++i) {
        CHECK(texels_of(ramp)[i].r == Approx(srgb8(i)).margin(1e-6));
        if (i > 0) CHECK(texels_of(ramp)[i].r > texels_of(ramp)[i - 1].r);
    }
}

TEST_CASE("texture_from_pixels: alpha stays linear, channels expand", "[assets][texture]") {
    SECTION("grey + alpha") {
        const std::vector<uint8_t> px = {128, 128, 255, 0};
        facet::Texture t = facet::texture_from_pixels(2, 1, 2, 8, px.data());
        require_texel(texels_of(t)[0], {srgb8(128), srgb8(128), srgb8(128), 128 / 255.0f});
        require_texel(texels_of(t)[1], {1, 1, 1, 0});
    }
    SECTION("RGB gets opaque alpha") {
        const std::vector<uint8_t> px = {255, 128, 0};
        facet::Texture t = facet::texture_from_pixels(1, 1, 3, 8, px.data());
        require_texel(texels_of(t)[0], {1, srgb8(128), 0, 1});
    }
    SECTION("RGBA") {
        const std::vector<uint8_t> px = {10, 20, 30, 64};
        facet::Texture t = facet::texture_from_pixels(1, 1, 4, 8, px.data());
        require_texel(texels_of(t)[0], {srgb8(10), srgb8(20), srgb8(30), 64 / 255.0f}, 1e-6f);
    }
    SECTION("16 bit, native byte order") {
        const std::vector<uint16_t> px = {65535, 0, 32768, 32768};
        facet::Texture t =
            facet::texture_from_pixels(2, 1, 2, 16, reinterpret_cast<const uint8_t*>(px.data()));
        require_texel(texels_of(t)[0], {1, 1, 1, 0});
        float c = static_cast<float>(srgb_to_linear(32768 / 65535.0));
        require_texel(texels_of(t)[1], {c, c, c, 32768 / 65535.0f}, kHalfStep);
    }
}

TEST_CASE("texture_from_pixels rejects impossible layouts", "[assets][texture]") {
    const std::vector<uint8_t> px(64, 0);
    CHECK_THROWS_AS(facet::texture_from_pixels(0, 1, 3, 8, px.data()), facet::Error);
    CHECK_THROWS_AS(facet::texture_from_pixels(1, -1, 3, 8, px.data()), facet::Error);
    CHECK_THROWS_AS(facet::texture_from_pixels(1, 1, 0, 8, px.data()), facet::Error);
    CHECK_THROWS_AS(facet::texture_from_pixels(1, 1, 5, 8, px.data()), facet::Error);
    CHECK_THROWS_AS(facet::texture_from_pixels(1, 1, 3, 12, px.data()), facet::Error);
    try {
        facet::texture_from_pixels(1, 1, 3, 4, px.data());
        FAIL("4-bit accepted");
    } catch (const facet::Error& e) {
        CHECK(e.code() == facet::ExitCode::invalid_input);
    }
}

TEST_CASE("load_texture reads PNG colour types and bit depths", "[assets][texture]") {
    TempDir dir("tex");
    SECTION("grey 8 bit") {
        std::string path =
            write_bytes(dir.file("grey.png"), make_png(2, 2, 0, 8, {0, 128, 255, 10}));
        facet::Texture t = facet::load_texture(path);
        REQUIRE(t.width == 2);
        REQUIRE(t.height == 2);
        REQUIRE(texels_of(t).size() == 4);
        require_texel(texels_of(t)[0], {0, 0, 0, 1});
        require_texel(texels_of(t)[1], glm::vec4(glm::vec3(srgb8(128)), 1));
        require_texel(texels_of(t)[2], {1, 1, 1, 1});
        require_texel(texels_of(t)[3], glm::vec4(glm::vec3(srgb8(10)), 1));
    }
    SECTION("grey + alpha 8 bit") {
        std::string path =
            write_bytes(dir.file("ga.png"), make_png(2, 1, 4, 8, {128, 128, 255, 0}));
        facet::Texture t = facet::load_texture(path);
        REQUIRE(texels_of(t).size() == 2);
        require_texel(texels_of(t)[0], {srgb8(128), srgb8(128), srgb8(128), 128 / 255.0f});
        require_texel(texels_of(t)[1], {1, 1, 1, 0});
    }
    SECTION("RGB 8 bit") {
        std::string path = write_bytes(dir.file("rgb.png"), make_png(1, 1, 2, 8, {255, 128, 0}));
        facet::Texture t = facet::load_texture(path);
        require_texel(texels_of(t).at(0), {1, srgb8(128), 0, 1});
    }
    SECTION("RGBA 8 bit") {
        std::string path =
            write_bytes(dir.file("rgba.png"), make_png(1, 1, 6, 8, {10, 20, 30, 64}));
        facet::Texture t = facet::load_texture(path);
        require_texel(texels_of(t).at(0), {srgb8(10), srgb8(20), srgb8(30), 64 / 255.0f}, 1e-6f);
    }
    SECTION("grey 16 bit") {
        // Big-endian samples: 65535, 0, 32768.
        std::string path = write_bytes(dir.file("grey16.png"),
                                       make_png(3, 1, 0, 16, {0xFF, 0xFF, 0, 0, 0x80, 0x00}));
        facet::Texture t = facet::load_texture(path);
        REQUIRE(texels_of(t).size() == 3);
        require_texel(texels_of(t)[0], {1, 1, 1, 1});
        require_texel(texels_of(t)[1], {0, 0, 0, 1});
        float c = static_cast<float>(srgb_to_linear(32768 / 65535.0));
        require_texel(texels_of(t)[2], {c, c, c, 1}, kHalfStep);
    }
    SECTION("RGBA 16 bit") {
        std::string path =
            write_bytes(dir.file("rgba16.png"),
                        make_png(1, 1, 6, 16, {0xFF, 0xFF, 0x00, 0x00, 0x80, 0x00, 0x80, 0x00}));
        facet::Texture t = facet::load_texture(path);
        float c = static_cast<float>(srgb_to_linear(32768 / 65535.0));
        require_texel(texels_of(t).at(0), {1, 0, c, 32768 / 65535.0f}, kHalfStep);
    }
    SECTION("rows run top to bottom") {
        std::string path = write_bytes(dir.file("rows.png"), make_png(1, 2, 0, 8, {255, 0}));
        facet::Texture t = facet::load_texture(path);
        require_texel(texels_of(t).at(0), {1, 1, 1, 1});
        require_texel(texels_of(t).at(1), {0, 0, 0, 1});
        require_texel(t.sample({0.5f, 0.25f}), {1, 1, 1, 1});  // centre of the top texel
        require_texel(t.sample({0.5f, 0.75f}), {0, 0, 0, 1});
    }
    SECTION("a PNG from facet's own encoder round-trips exact values") {
        facet::ColorImage img(2, 1, {0, 0, 0, 1});
        img.at(1, 0) = {1, 0, 1, 1};
        auto bytes = facet::encode_png_color(img, 9);
        std::string path = write_bytes(dir.file("own.png"), bytes);
        facet::Texture t = facet::load_texture(path);
        require_texel(texels_of(t).at(0), {0, 0, 0, 1});
        require_texel(texels_of(t).at(1), {1, 0, 1, 1});
    }
    SECTION("a larger PNG spanning several deflate blocks") {
        const int w = 300, h = 300;  // 90 000 grey bytes + filters > one 64 KiB block
        std::vector<uint8_t> px(w * h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) px[y * w + x] = static_cast<uint8_t>((x + 3 * y) & 255);
        std::string path = write_bytes(dir.file("big.png"), make_png(w, h, 0, 8, px));
        facet::Texture t = facet::load_texture(path);
        REQUIRE(t.width == w);
        REQUIRE(t.height == h);
        for (int y : {0, 150, 299})
            for (int x : {0, 7, 299})
                CHECK(t.texel(0, x, y).g == Approx(srgb8((x + 3 * y) & 255)).margin(1e-6));
    }
}

TEST_CASE("load_texture reads JPEG", "[assets][texture]") {
    TempDir dir("tex");
    SECTION("colour") {
        std::vector<uint8_t> px;
        for (int i = 0; i < 16 * 16; ++i) px.insert(px.end(), {200, 100, 50});
        std::string path = dir.file("solid.jpg");
        REQUIRE(stbi_write_jpg(path.c_str(), 16, 16, 3, px.data(), 100) != 0);
        facet::Texture t = facet::load_texture(path);
        REQUIRE(t.width == 16);
        REQUIRE(t.height == 16);
        // JPEG is lossy: allow a few levels either way around each byte.
        for (const auto& texel : texels_of(t)) {
            CHECK(texel.r >= srgb8(196));
            CHECK(texel.r <= srgb8(204));
            CHECK(texel.g >= srgb8(96));
            CHECK(texel.g <= srgb8(104));
            CHECK(texel.b >= srgb8(46));
            CHECK(texel.b <= srgb8(54));
            CHECK(texel.a == 1.0f);
        }
    }
    SECTION("grey") {
        std::vector<uint8_t> px(8 * 8, 128);
        std::string path = dir.file("grey.jpg");
        REQUIRE(stbi_write_jpg(path.c_str(), 8, 8, 1, px.data(), 100) != 0);
        facet::Texture t = facet::load_texture(path);
        REQUIRE(texels_of(t).size() == 64);
        for (const auto& texel : texels_of(t)) {
            CHECK(texel.r == texel.g);
            CHECK(texel.g == texel.b);
            CHECK(texel.r == Approx(srgb8(128)).margin(srgb8(130) - srgb8(128)));
        }
    }
    SECTION("real JPEG from the OBJ test models") {
        facet::Texture t = facet::load_texture("/usr/share/assimp/models/OBJ/SpiderTex.jpg");
        CHECK(t.width > 0);
        CHECK(t.height > 0);
        const std::vector<glm::vec4> texels = texels_of(t);
        CHECK(texels.size() == static_cast<size_t>(t.width) * t.height);
        for (size_t i = 0; i < texels.size(); i += 97) {
            for (int c = 0; c < 4; ++c) {
                CHECK(texels[i][c] >= 0.0f);
                CHECK(texels[i][c] <= 1.0f);
            }
        }
    }
}

TEST_CASE("bilinear sampling between texel centres", "[assets][texture]") {
    // Two texels, 0 and 1: their centres are at u = 0.25 and u = 0.75.
    facet::Texture t = grey_row({0, 1}, facet::Wrap::clamp);
    CHECK(t.sample({0.25f, 0.5f}).r == Approx(0.0f).margin(1e-6));
    CHECK(t.sample({0.75f, 0.5f}).r == Approx(1.0f));
    CHECK(t.sample({0.5f, 0.5f}).r == Approx(0.5f));
    CHECK(t.sample({0.375f, 0.5f}).r == Approx(0.25f));
    CHECK(t.sample({0.625f, 0.5f}).r == Approx(0.75f));
    // The same along v.
    facet::Texture v = grey_row({0, 1}, facet::Wrap::clamp, true);
    CHECK(v.sample({0.5f, 0.25f}).r == Approx(0.0f).margin(1e-6));
    CHECK(v.sample({0.5f, 0.5f}).r == Approx(0.5f));
    CHECK(v.sample({0.5f, 0.6875f}).r == Approx(0.875f));
    // Both axes at once: a 2x2 with one white texel (bottom right).
    facet::Texture q =
        facet::Texture::from_linear(2, 2, {{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {1, 1, 1, 1}},
                                    facet::Texture::Format::srgb8);
    q.sampler.wrap_s = q.sampler.wrap_t = facet::Wrap::clamp;
    CHECK(q.sample({0.5f, 0.5f}).r == Approx(0.25f));
    CHECK(q.sample({0.625f, 0.625f}).r == Approx(0.5625f));  // 0.75 * 0.75
    CHECK(q.sample({0.5f, 0.5f}).a == Approx(1.0f));
}

TEST_CASE("repeat and clamp wrapping at the edges", "[assets][texture]") {
    facet::Texture repeat = grey_row({0, 1}, facet::Wrap::repeat);
    facet::Texture clamp = grey_row({0, 1}, facet::Wrap::clamp);
    SECTION("at u = 0 repeat blends with the last texel, clamp does not") {
        CHECK(repeat.sample({0.0f, 0.5f}).r == Approx(0.5f));
        CHECK(clamp.sample({0.0f, 0.5f}).r == Approx(0.0f).margin(1e-6));
    }
    SECTION("at u = 1") {
        CHECK(repeat.sample({1.0f, 0.5f}).r == Approx(0.5f));
        CHECK(clamp.sample({1.0f, 0.5f}).r == Approx(1.0f));
    }
    SECTION("outside [0, 1]") {
        CHECK(repeat.sample({1.25f, 0.5f}).r == Approx(0.0f).margin(1e-6));
        CHECK(repeat.sample({-0.25f, 0.5f}).r == Approx(1.0f));
        CHECK(repeat.sample({-0.75f, 0.5f}).r == Approx(0.0f).margin(1e-6));
        CHECK(repeat.sample({7.75f, 0.5f}).r == Approx(1.0f));
        CHECK(clamp.sample({-3.0f, 0.5f}).r == Approx(0.0f).margin(1e-6));
        CHECK(clamp.sample({42.0f, 0.5f}).r == Approx(1.0f));
        CHECK(repeat.sample({1000.25f, 0.5f}).r == Approx(0.0f).margin(1e-3));
    }
    SECTION("clamp holds the edge texel however far out") {
        for (float u : {2e7f, 1e8f, 3.3e9f, 1e30f}) {
            INFO("u = " << u);
            CHECK(clamp.sample({u, 0.5f}).r == Approx(1.0f));
            CHECK(clamp.sample({-u, 0.5f}).r == Approx(0.0f).margin(1e-6));
        }
        facet::Texture vc = grey_row({0, 1}, facet::Wrap::clamp, true);
        CHECK(vc.sample({0.5f, 1e8f}).r == Approx(1.0f));
        CHECK(vc.sample({0.5f, -1e8f}).r == Approx(0.0f).margin(1e-6));
    }
    SECTION("v wraps the same way") {
        facet::Texture vr = grey_row({0, 1}, facet::Wrap::repeat, true);
        facet::Texture vc = grey_row({0, 1}, facet::Wrap::clamp, true);
        CHECK(vr.sample({0.5f, 0.0f}).r == Approx(0.5f));
        CHECK(vc.sample({0.5f, 0.0f}).r == Approx(0.0f).margin(1e-6));
        CHECK(vr.sample({0.5f, -0.25f}).r == Approx(1.0f));
        CHECK(vc.sample({0.5f, 2.0f}).r == Approx(1.0f));
    }
    SECTION("extreme and non-finite coordinates stay in range") {
        const float inf = std::numeric_limits<float>::infinity();
        const float nan = std::numeric_limits<float>::quiet_NaN();
        for (const auto& t : {repeat, clamp})
            for (glm::vec2 uv : {glm::vec2(1e30f, 0.5f), glm::vec2(-1e30f, -1e30f),
                                 glm::vec2(inf, 0.5f), glm::vec2(0.5f, -inf), glm::vec2(nan, 0.5f),
                                 glm::vec2(0.5f, nan), glm::vec2(3e9f, 3e9f)}) {
                glm::vec4 s = t.sample(uv);
                for (int c = 0; c < 4; ++c) {
                    CHECK(std::isfinite(s[c]));
                    CHECK(s[c] >= 0.0f);
                    CHECK(s[c] <= 1.0f);
                }
            }
    }
    SECTION("a 1x1 texture is the same everywhere") {
        facet::Texture one = grey_row({0.3f}, facet::Wrap::repeat);
        for (float u : {-5.5f, 0.0f, 0.37f, 1.0f, 12.25f})
            CHECK(one.sample({u, u * 0.5f}).r == Approx(0.3f).margin(kHalfStep));
    }
}

TEST_CASE("load_texture errors name the file", "[assets][texture]") {
    TempDir dir("tex");
    SECTION("missing file") {
        require_input_error([&] { facet::load_texture(dir.file("absent.png")); }, "absent.png");
    }
    SECTION("empty file") {
        std::string path = write_bytes(dir.file("empty.png"), {});
        require_input_error([&] { facet::load_texture(path); }, "empty.png");
    }
    SECTION("random bytes") {
        std::vector<uint8_t> junk(1000);
        uint32_t x = 99;
        for (auto& b : junk) b = static_cast<uint8_t>((x = x * 1103515245u + 12345u) >> 24);
        std::string path = write_bytes(dir.file("junk.png"), junk);
        require_input_error([&] { facet::load_texture(path); }, "junk.png");
    }
    SECTION("text with a .jpg name") {
        std::string path =
            facet::test::write_text(dir.file("notes.jpg"), "this is not a picture\n");
        require_input_error([&] { facet::load_texture(path); }, "notes.jpg");
    }
    SECTION("truncated PNGs") {
        auto good = make_png(16, 16, 2, 8, std::vector<uint8_t>(16 * 16 * 3, 77));
        for (size_t keep : {size_t(8), size_t(20), size_t(33), size_t(60), good.size() - 40}) {
            INFO("kept " << keep << " bytes");
            std::string path = write_bytes(dir.file("cut.png"),
                                           std::vector<uint8_t>(good.begin(), good.begin() + keep));
            require_input_error([&] { facet::load_texture(path); }, "cut.png");
        }
    }
    SECTION("PNG header claiming enormous dimensions") {
        auto png = make_png(1, 1, 2, 8, {1, 2, 3});
        // Patch IHDR to 100000 x 100000 and fix its CRC.
        std::vector<uint8_t> ihdr(png.begin() + 12, png.begin() + 29);  // "IHDR" + 13 bytes
        for (int i = 0; i < 2; ++i) {
            uint32_t v = 100000;
            for (int k = 0; k < 4; ++k)
                ihdr[4 + 4 * i + k] = static_cast<uint8_t>(v >> (24 - 8 * k));
        }
        std::copy(ihdr.begin(), ihdr.end(), png.begin() + 12);
        uint32_t crc = crc32(ihdr.data(), ihdr.size());
        for (int k = 0; k < 4; ++k) png[29 + k] = static_cast<uint8_t>(crc >> (24 - 8 * k));
        std::string path = write_bytes(dir.file("huge.png"), png);
        require_input_error([&] { facet::load_texture(path); }, "huge.png");
    }
    SECTION("a folder") {
        std::filesystem::create_directories(dir.file("folder.png"));
        require_input_error([&] { facet::load_texture(dir.file("folder.png")); }, "folder.png");
    }
}

TEST_CASE("an empty texture samples as white", "[assets][texture]") {
    facet::Texture t;
    require_texel(t.sample({0.5f, 0.5f}), {1, 1, 1, 1});
}
