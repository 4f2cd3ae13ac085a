// The PNG writer (output/png_writer.cpp, libdeflate): what it writes
// decodes with libpng to the very bytes it encoded, at every compression
// level, for colour with and without alpha and for 16-bit depth; and its
// chunks carry correct CRCs.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>

#include "output/atomic_file.hpp"
#include "output/deflate.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

using namespace facet;

namespace {

// The 8-bit sRGB byte of a linear value, computed here independently.
int srgb_byte(float linear) {
    const double v = std::clamp(static_cast<double>(linear), 0.0, 1.0);
    const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    return static_cast<int>(std::lround(s * 255));
}

DecodedPng round_trip(const std::vector<uint8_t>& bytes, const std::string& path) {
    write_file_atomically(path, bytes);
    return read_png(path);
}

}  // namespace

TEST_CASE("PNG writer: decodes to what it encoded, every level", "[output][png]") {
    test::TempDir dir("png-writer");
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    HalfColorImage image(37, 23);  // odd sizes: no row is a multiple of anything
    for (Rgba16F& p : image.pixels) p = to_half(glm::vec4(unit(rng), unit(rng), unit(rng), 1.0f));
    for (int level = 0; level <= 9; ++level) {
        const DecodedPng png = round_trip(encode_png_color(image, level), dir.file("c.png"));
        REQUIRE(png.width == 37);
        REQUIRE(png.height == 23);
        REQUIRE(png.channels == 3);  // opaque: RGB
        for (int y = 0; y < 23; ++y)
            for (int x = 0; x < 37; ++x) {
                const glm::vec4 c = to_float(image.at(x, y));
                for (int k = 0; k < 3; ++k)
                    REQUIRE(png.samples[(static_cast<size_t>(y) * 37 + x) * 3 + k] ==
                            srgb_byte(c[k]));
            }
    }
    // Translucent pixels keep alpha, as linear bytes; the colour, held
    // premultiplied, is written straight (divided by alpha), as PNG defines it.
    image.at(3, 4) = to_half(glm::vec4(0.125f, 0.125f, 0.125f, 0.25f));
    const DecodedPng rgba = round_trip(encode_png_color(image, 1), dir.file("a.png"));
    REQUIRE(rgba.channels == 4);
    CHECK(rgba.samples[(4 * 37 + 3) * 4 + 3] == 64);  // round(0.25 * 255)
    CHECK(rgba.samples[(4 * 37 + 3) * 4] == srgb_byte(0.5f));
    // Fully transparent: black, whatever the colour channels hold.
    image.at(5, 4) = to_half(glm::vec4(0.0f));
    const DecodedPng clear = round_trip(encode_png_color(image, 1), dir.file("t.png"));
    CHECK(clear.samples[(4 * 37 + 5) * 4 + 3] == 0);
    CHECK(clear.samples[(4 * 37 + 5) * 4] == 0);
}

TEST_CASE("PNG writer: 16-bit depth follows its mapping", "[output][png]") {
    test::TempDir dir("png-depth");
    DepthImage depth(5, 3, INFINITY);
    depth.at(0, 0) = 4.0f;  // near end: white
    depth.at(1, 0) = 5.0f;  // far end: black
    depth.at(2, 0) = 4.5f;  // halfway
    depth.at(3, 0) = 3.0f;  // nearer than the range: clamped white
    const DecodedPng png =
        round_trip(encode_png(png_depth_samples(depth, glm::vec2(4, 5)), 1), dir.file("d.png"));
    REQUIRE(png.bit_depth == 16);
    REQUIRE(png.channels == 1);
    CHECK(png.samples[0] == 65535);
    CHECK(png.samples[1] == 0);
    CHECK(png.samples[2] == 32768);
    CHECK(png.samples[3] == 65535);
    CHECK(png.samples[4] == 0);  // background
}

TEST_CASE("PNG writer: chunk CRCs and text", "[output][png]") {
    // CRC-32 of "IEND" is the constant every PNG ends with.
    const uint8_t iend[4] = {'I', 'E', 'N', 'D'};
    CHECK(crc32(0, iend, 4) == 0xAE426082u);
    HalfColorImage image(4, 4, to_half(glm::vec4(1, 0, 0, 1)));
    const std::vector<uint8_t> bytes = encode_png_color(image, 1, {{"Software", "facet"}});
    // The file ends with IEND and its CRC, and holds the text chunk.
    REQUIRE(bytes.size() > 12);
    const uint8_t tail[8] = {'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    CHECK(std::equal(tail, tail + 8, bytes.end() - 8));
    const std::string all(bytes.begin(), bytes.end());
    CHECK(all.find(std::string("tEXtSoftware") + '\0' + "facet") != std::string::npos);
}

TEST_CASE("a PNG whose header asks for more memory than there is is refused, naming it",
          "[output][png]") {
    // The signature, an IHDR of 1,000,000 x 1,000,000 RGBA pixels (libpng's
    // own limits allow it), an empty IDAT and IEND: 4 TB of samples.
    std::vector<uint8_t> file = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    auto chunk = [&](const char* type, const std::vector<uint8_t>& data) {
        const uint32_t size = static_cast<uint32_t>(data.size());
        for (int shift = 24; shift >= 0; shift -= 8) file.push_back(uint8_t(size >> shift));
        std::vector<uint8_t> typed(type, type + 4);
        typed.insert(typed.end(), data.begin(), data.end());
        file.insert(file.end(), typed.begin(), typed.end());
        const uint32_t crc = facet::crc32(0, typed.data(), typed.size());
        for (int shift = 24; shift >= 0; shift -= 8) file.push_back(uint8_t(crc >> shift));
    };
    const uint8_t million[4] = {0x00, 0x0f, 0x42, 0x40};
    std::vector<uint8_t> header(million, million + 4);
    header.insert(header.end(), million, million + 4);
    header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, no filter, no interlace
    chunk("IHDR", header);
    chunk("IDAT", {});
    chunk("IEND", {});
    try {
        facet::decode_png(file, "giant.png");
        FAIL("a 1000000x1000000 PNG was read");
    } catch (const facet::Error& e) {
        CHECK(e.code() == facet::ExitCode::invalid_input);
        CHECK_THAT(std::string(e.what()), Catch::Matchers::Contains("giant.png") &&
                                              Catch::Matchers::Contains("1000000x1000000") &&
                                              Catch::Matchers::Contains("available"));
    }
}
