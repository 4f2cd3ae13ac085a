// EXR compression chosen per file (output.exr_compression): every method
// writes a standard file that OpenEXR's own reader opens, the lossless
// ones give back every sample exactly, dwaa keeps float channels exact,
// and a whole run's bytes do not depend on the thread count.
#include <catch2/catch.hpp>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <cmath>
#include <random>

#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "render_hashes.hpp"
#include "scene_support.hpp"

using namespace facet;

namespace {

Imf::Compression library_name(ExrCompression c) {
    switch (c) {
        case ExrCompression::none:
            return Imf::NO_COMPRESSION;
        case ExrCompression::rle:
            return Imf::RLE_COMPRESSION;
        case ExrCompression::zips:
            return Imf::ZIPS_COMPRESSION;
        case ExrCompression::zip:
            return Imf::ZIP_COMPRESSION;
        case ExrCompression::piz:
            return Imf::PIZ_COMPRESSION;
        case ExrCompression::dwaa:
            return Imf::DWAA_COMPRESSION;
    }
    return Imf::NUM_COMPRESSION_METHODS;
}

// 67 x 45: more than one chunk for every method (1, 16 and 32 scanlines),
// the last one short; half smooth (it compresses), half noise (it does not).
struct TestFrame {
    HalfColorImage color{67, 45};
    DepthImage depth{67, 45};
    TestFrame() {
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> unit(0.0f, 2.0f);
        for (int y = 0; y < 45; ++y)
            for (int x = 0; x < 67; ++x) {
                const float smooth = 0.01f * static_cast<float>(x + y);
                const bool noisy = y >= 22;
                color.at(x, y) = to_half(noisy ? glm::vec4(unit(rng), unit(rng), unit(rng), 1.0f)
                                               : glm::vec4(smooth, 0.5f, 1.0f - smooth, 1.0f));
                depth.at(x, y) = noisy ? unit(rng) * 100.0f : (x == 3 ? INFINITY : 4.0f + smooth);
            }
    }
};

}  // namespace

TEST_CASE("every EXR compression is read back by OpenEXR", "[output][exr]") {
    test::TempDir dir("exr-compression");
    const TestFrame frame;
    for (size_t m = 0; m < kExrCompressionNames.size(); ++m) {
        const auto method = static_cast<ExrCompression>(m);
        INFO(exr_compression_name(method));
        const std::string c_path = dir.file("c.exr"), z_path = dir.file("z.exr");
        write_file_atomically(c_path,
                              encode_exr_color(frame.color, {{"facet/scene", "x"}}, method));
        write_file_atomically(z_path, encode_exr_depth(frame.depth, {}, method));
        CHECK(Imf::InputFile(c_path.c_str()).header().compression() == library_name(method));
        CHECK(Imf::InputFile(z_path.c_str()).header().compression() == library_name(method));
        const DecodedExr c = read_exr(c_path), z = read_exr(z_path);
        REQUIRE(c.channel_names == std::vector<std::string>{"A", "B", "G", "R"});
        REQUIRE(z.channel_names == std::vector<std::string>{"Z"});
        const bool lossy = method == ExrCompression::dwaa;
        double worst = 0;
        for (size_t i = 0; i < frame.color.pixels.size(); ++i) {
            const glm::vec4 want = to_float(frame.color.pixels[i]);
            const glm::vec4 got(c.channels[3][i], c.channels[2][i], c.channels[1][i],
                                c.channels[0][i]);
            for (int k = 0; k < 4; ++k)
                worst = std::max(worst, static_cast<double>(std::abs(got[k] - want[k])));
            // Float channels stay exact even under dwaa.
            const float d = frame.depth.pixels[i], zd = z.channels[0][i];
            REQUIRE((std::isinf(d) ? std::isinf(zd) : zd == d));
        }
        if (lossy)
            CHECK(worst < 0.1);
        else
            CHECK(worst == 0);
    }
}

TEST_CASE("each EXR compression gives the same bytes every time", "[output][exr]") {
    const TestFrame frame;
    for (size_t m = 0; m < kExrCompressionNames.size(); ++m) {
        const auto method = static_cast<ExrCompression>(m);
        INFO(exr_compression_name(method));
        CHECK(encode_exr_color(frame.color, {}, method) ==
              encode_exr_color(frame.color, {}, method));
    }
    // The methods really differ: the choice reaches the file.
    CHECK(encode_exr_depth(frame.depth, {}, ExrCompression::none) !=
          encode_exr_depth(frame.depth, {}, ExrCompression::zip));
}

TEST_CASE("exr_compression per pass, one for all, and the default", "[scene][exr]") {
    test::TempDir dir("exr-compression-keys");
    const std::string objects = "objects:\n  - primitive: cube\n";
    auto load = [&](const std::string& output) {
        const std::string path =
            test::write_text(dir.file("s.yaml"), "output:\n" + output + objects);
        return test::load(path).output.exr_compression;
    };
    const ExrCompressionChoice fallback = load("  size: [8, 8]\n");
    CHECK(fallback.of(Pass::color) == ExrCompression::zip);
    CHECK(fallback.of(Pass::depth) == ExrCompression::none);
    CHECK(fallback.of(Pass::normal) == ExrCompression::zip);
    CHECK(fallback.all == ExrCompression::zip);  // a multilayer file
    const ExrCompressionChoice one = load("  exr_compression: rle\n");
    CHECK(one.of(Pass::color) == ExrCompression::rle);
    CHECK(one.of(Pass::normal) == ExrCompression::rle);
    CHECK(one.of(Pass::depth) == ExrCompression::rle);
    CHECK(load("  exr_compression: {color: piz}\n").of(Pass::depth) == ExrCompression::zip);
    const ExrCompressionChoice mapped =
        load("  exr_compression: {default: piz, depth: none, normal: dwaa}\n");
    CHECK(mapped.all == ExrCompression::piz);
    CHECK(mapped.of(Pass::color) == ExrCompression::piz);
    CHECK(mapped.of(Pass::depth) == ExrCompression::none);
    CHECK(mapped.of(Pass::normal) == ExrCompression::dwaa);
}

TEST_CASE("a run's EXR files are identical at 1 and 3 threads with every method",
          "[determinism][exr]") {
    for (const char* methods :
         {"{color: rle, depth: none}", "{color: piz, depth: zips}", "{color: dwaa, depth: zip}"}) {
        INFO(methods);
        test::TempDir a("exrc1"), b("exrc3");
        const std::vector<Override> chosen = {{"output.exr_compression", methods, "test"}};
        auto one = test::render_hashes("tests/scenes/shapes.yaml", 1, {1, 2}, a.path(), 1,
                                       "[color, depth]", "", chosen);
        auto three = test::render_hashes("tests/scenes/shapes.yaml", 3, {1, 2}, b.path(), 1,
                                         "[color, depth]", "", chosen);
        REQUIRE(one.size() == 8);
        CHECK(one == three);
    }
}
