// The EXR writer (output/exr_writer.cpp: OpenEXR's C core with libdeflate ZIP
// chunks) read back by OpenEXR's C++ reader: every channel's samples come
// back exactly, for smooth data that compresses and for noise that does not
// (the chunk is then stored raw), with the header's attributes.
#include <catch2/catch.hpp>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cmath>
#include <cstring>
#include <random>

#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "support.hpp"

using namespace facet;

TEST_CASE("EXR writer: colour and depth read back exactly", "[output][exr]") {
    test::TempDir dir("exr-writer");
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 2.0f);
    for (bool noisy : {false, true}) {
        // 41 x 37: two chunks of 16 scanlines and a short one.
        HalfColorImage color(41, 37);
        DepthImage depth(41, 37);
        for (int y = 0; y < 37; ++y)
            for (int x = 0; x < 41; ++x) {
                const float smooth = 0.01f * static_cast<float>(x + y);
                const glm::vec4 c = noisy ? glm::vec4(unit(rng), unit(rng), unit(rng), unit(rng))
                                          : glm::vec4(smooth, 0.5f, 1.0f - smooth, 1.0f);
                color.at(x, y) = to_half(c);
                depth.at(x, y) = noisy ? unit(rng) * 100.0f : (x == 3 ? INFINITY : 4.0f + smooth);
            }
        write_file_atomically(dir.file("c.exr"), encode_exr_color(color, {{"facet/scene", "x"}}));
        write_file_atomically(dir.file("z.exr"), encode_exr_depth(depth));
        const DecodedExr c = read_exr(dir.file("c.exr"));
        const DecodedExr z = read_exr(dir.file("z.exr"));
        REQUIRE(c.width == 41);
        REQUIRE(c.height == 37);
        REQUIRE(c.channel_names == std::vector<std::string>{"A", "B", "G", "R"});
        REQUIRE(z.channel_names == std::vector<std::string>{"Z"});
        for (int i = 0; i < 41 * 37; ++i) {
            const glm::vec4 want = to_float(color.pixels[static_cast<size_t>(i)]);
            REQUIRE(c.channels[3][static_cast<size_t>(i)] == want.r);
            REQUIRE(c.channels[2][static_cast<size_t>(i)] == want.g);
            REQUIRE(c.channels[1][static_cast<size_t>(i)] == want.b);
            REQUIRE(c.channels[0][static_cast<size_t>(i)] == want.a);
            const float d = depth.pixels[static_cast<size_t>(i)];
            const float got = z.channels[0][static_cast<size_t>(i)];
            REQUIRE((std::isinf(d) ? std::isinf(got) : got == d));
        }
        Imf::InputFile file(dir.file("c.exr").c_str());
        const auto* scene = file.header().findTypedAttribute<Imf::StringAttribute>("facet/scene");
        REQUIRE(scene);
        CHECK(scene->value() == "x");
        CHECK(file.header().compression() == Imf::ZIP_COMPRESSION);
    }
}
