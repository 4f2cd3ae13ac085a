// The run and Huffman deflate coder (output/fast_deflate.cpp, level 1 of
// zlib_compress): zlib's own inflater, which libpng and OpenEXR read with,
// gives back every input exactly; runs shrink; the bytes never change.
#include <catch2/catch.hpp>

#include <zlib.h>

#include <random>

#include "output/deflate.hpp"
#include "output/encoders.hpp"
#include "output/fast_deflate.hpp"

using namespace facet;

namespace {

std::vector<uint8_t> inflate_with_zlib(const std::vector<uint8_t>& stream, size_t size) {
    std::vector<uint8_t> out(size + 1);
    uLongf length = static_cast<uLongf>(out.size());
    REQUIRE(uncompress(out.data(), &length, stream.data(), static_cast<uLong>(stream.size())) ==
            Z_OK);
    out.resize(length);
    return out;
}

std::vector<uint8_t> compressed(const std::vector<uint8_t>& data, size_t distance = 1) {
    std::vector<uint8_t> out;
    zlib_compress_runs(data.data(), data.size(), distance, out);
    return out;
}

// Runs of every length from 1 to 600 of random bytes, some of one value
// after another: copies of every length symbol, and split runs.
std::vector<uint8_t> runs_of_every_length() {
    std::mt19937 rng(3);
    std::vector<uint8_t> data;
    for (size_t length = 1; length <= 600; ++length)
        data.insert(data.end(), length, static_cast<uint8_t>(rng() % 4));
    return data;
}

}  // namespace

TEST_CASE("fast deflate: zlib inflates every input back exactly", "[output][deflate]") {
    std::mt19937 rng(9);
    std::vector<std::pair<const char*, std::vector<uint8_t>>> inputs = {
        {"empty", {}},
        {"one byte", {7}},
        {"two bytes", {7, 7}},
        {"a run of five", {1, 1, 1, 1, 1}},
        {"runs of every length", runs_of_every_length()},
        {"one megabyte of zeros: several blocks", std::vector<uint8_t>(1 << 20, 0)},
    };
    std::vector<uint8_t> noise(700000);  // three blocks, every byte value: all literals
    for (uint8_t& b : noise) b = static_cast<uint8_t>(rng());
    inputs.push_back({"noise", noise});
    // A run that goes on across a block's end (blocks are 2^18 bytes).
    std::vector<uint8_t> straddle(300000);
    for (size_t i = 0; i < straddle.size(); ++i)
        straddle[i] = i > 262000 && i < 263000 ? 200 : static_cast<uint8_t>(rng() % 16);
    inputs.push_back({"a run across blocks", straddle});
    // A slope as a PNG's Sub filter leaves it: each 3-byte pixel (1, 2, 3),
    // which repeats at distance 3 only.
    std::vector<uint8_t> slope(30000);
    for (size_t i = 0; i < slope.size(); ++i) slope[i] = static_cast<uint8_t>(i % 3 + 1);
    inputs.push_back({"a slope", slope});
    for (const auto& [name, data] : inputs)
        for (size_t distance = 1; distance <= kMaxRunDistance; ++distance) {
            INFO(name << ", runs at distance " << distance);
            const std::vector<uint8_t> stream = compressed(data, distance);
            CHECK(inflate_with_zlib(stream, data.size()) == data);
            CHECK(compressed(data, distance) == stream);
        }
    // Runs at the right distance find the slope.
    CHECK(compressed(slope, 3).size() * 10 < compressed(slope, 1).size());
    // Runs cost a few bits per 258 bytes.
    CHECK(compressed(std::vector<uint8_t>(1 << 20, 0)).size() < 3000);
}

TEST_CASE("fast deflate: level 1 of zlib_compress, level 2 libdeflate's", "[output][deflate]") {
    const std::vector<uint8_t> data = runs_of_every_length();
    std::vector<uint8_t> level1, level2;
    zlib_compress(data.data(), data.size(), 1, level1);
    zlib_compress(data.data(), data.size(), 2, level2);
    CHECK(level1 == compressed(data));
    CHECK(level2 != level1);
    CHECK(inflate_with_zlib(level2, data.size()) == data);
}

TEST_CASE("fast deflate: PNG files decode through libpng to the same samples",
          "[output][deflate][png]") {
    std::mt19937 rng(4);
    // The layouts facet writes (16-bit grey depth, 8-bit grey, RGB and RGBA),
    // and 16-bit colour, which facet compares when others write it: its
    // samples must come back as stored, neither linearised nor premultiplied.
    for (const auto& [channels, bit_depth] :
         {std::pair{1, 16}, {1, 8}, {3, 8}, {4, 8}, {3, 16}, {4, 16}}) {
        INFO(channels << " channels, " << bit_depth << " bits");
        PngSamples samples{97, 61, channels, bit_depth, {}};
        samples.bytes.resize(static_cast<size_t>(97 * 61 * channels * bit_depth / 8));
        // A flat left half (runs) and a noisy right half (literals).
        const size_t row = samples.bytes.size() / 61;
        for (size_t i = 0; i < samples.bytes.size(); ++i)
            samples.bytes[i] = i % row < row / 2 ? 40 : static_cast<uint8_t>(rng());
        const DecodedPng png = decode_png(encode_png(samples, 1), "test");
        REQUIRE(png.width == 97);
        REQUIRE(png.channels == channels);
        REQUIRE(png.samples.size() == samples.bytes.size() / (bit_depth / 8));
        for (size_t i = 0; i < png.samples.size(); ++i)
            REQUIRE(png.samples[i] == samples.sample(i));
    }
}
