// Half-float conversions (core/half.hpp): every half survives the round trip,
// and floats go to the nearest half, ties to even, checked against the
// halves' own values rather than another converter.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "core/half.hpp"

using namespace facet;

TEST_CASE("half: every finite half converts to float and back unchanged", "[half]") {
    for (uint32_t h = 0; h < 0x10000; ++h) {
        const float f = half_to_float(static_cast<uint16_t>(h));
        if (std::isnan(f)) {
            CHECK((float_to_half(f) & 0x7c00) == 0x7c00);  // stays a NaN
            CHECK((float_to_half(f) & 0x03ff) != 0);
            continue;
        }
        INFO("half " << h);
        if (std::isinf(f)) {  // stored saturated: the largest finite half
            REQUIRE(float_to_half(f) == (f > 0 ? 0x7bff : 0xfbff));
            continue;
        }
        REQUIRE(float_to_half(f) == h);
    }
    CHECK(half_to_float(0x3c00) == 1.0f);
    CHECK(half_to_float(0x0001) == std::ldexp(1.0f, -24));  // smallest subnormal
    CHECK(half_to_float(0x7bff) == 65504.0f);               // largest finite
}

TEST_CASE("half: floats round to the nearest half, ties to even", "[half]") {
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> bits(0, 0x477fffff);  // up to 65535.99
    for (int i = 0; i < 200000; ++i) {
        uint32_t b = bits(rng);
        float f;
        std::memcpy(&f, &b, sizeof f);
        const uint16_t h = float_to_half(f);
        const double got = half_to_float(h);
        // The neighbours of the chosen half are no nearer.
        const double up = half_to_float(static_cast<uint16_t>(h + 1));
        const double down = h > 0 ? half_to_float(static_cast<uint16_t>(h - 1)) : -got;
        const double error = std::abs(got - f);
        INFO("float " << f << " -> half " << h);
        REQUIRE(error <= std::abs(up - f));
        REQUIRE(error <= std::abs(down - f));
        if (error == std::abs(up - f) || error == std::abs(down - f)) REQUIRE((h & 1) == 0);
    }
    CHECK(float_to_half(65519.0f) == 0x7bff);
    CHECK(float_to_half_portable(simd::splat(65520.0f))[0] == 0x7c00);  // IEEE: infinity
    CHECK(float_to_half(-2.0f) == 0xc000);
    CHECK(float_to_half(std::ldexp(1.0f, -25)) == 0);       // a tie below the smallest: even
    CHECK(float_to_half(std::ldexp(1.5f, -25)) == 0x0001);  // more than half: up
}

TEST_CASE("half: facet stores values past the half range as the largest finite half", "[half]") {
    // IEEE rounds 65520 and above to infinity, which tone curves cannot map
    // to white; facet saturates (docs/passes.md).
    const float inf = std::numeric_limits<float>::infinity();
    for (float f : {65520.0f, 1e5f, 1.6e9f, 3e38f, inf}) {
        INFO(f);
        CHECK(float_to_half(f) == 0x7bff);
        CHECK(float_to_half(-f) == 0xfbff);
    }
    CHECK(std::isnan(half_to_float(float_to_half(std::nanf("")))));
    CHECK(to_float(to_half(glm::vec4(inf, 7e4f, 1.0f, 1.0f))) ==
          glm::vec4(65504.0f, 65504.0f, 1.0f, 1.0f));
}

TEST_CASE("half: the build's conversion and the portable one agree bit for bit", "[half]") {
    // With F16C the build converts with the instruction; without, both are
    // the portable code and this checks nothing new.
    std::mt19937 rng(11);
    std::uniform_int_distribution<uint32_t> any;
    for (int i = 0; i < 400000; ++i) {
        simd::vi bits;
        for (int k = 0; k < simd::kLanes; ++k) bits[k] = static_cast<int32_t>(any(rng));
        simd::vf values;
        std::memcpy(&values, &bits, sizeof values);
        const simd::vi a = float_to_half(values),
                       b = float_to_half_portable(saturate_to_half_range(values));
        for (int k = 0; k < simd::kLanes; ++k) REQUIRE(a[k] == b[k]);
    }
}
