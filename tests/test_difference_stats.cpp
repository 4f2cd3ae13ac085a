// Difference statistics (compare/difference_stats.cpp) on images whose
// figures are worked out here by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "compare/difference_stats.hpp"

using namespace facet;

TEST_CASE("difference statistics: mean, RMS, max and where, share over a threshold", "[compare]") {
    // 4 x 2 pixels, 3 channels; b differs from a in two samples:
    // pixel (1, 0) channel 2 by 6, pixel (3, 1) channel 0 by 2.
    std::vector<float> a(4 * 2 * 3, 100.0f), b = a;
    b[(0 * 4 + 1) * 3 + 2] = 106.0f;
    b[(1 * 4 + 3) * 3 + 0] = 98.0f;
    const SampleImage ia{4, 2, 3, a}, ib{4, 2, 3, b};
    const DifferenceStats s = difference_stats(ia, ib, 3.0);
    CHECK(s.pixels == 8);
    CHECK(s.mean == Approx(8.0 / 24));
    CHECK(s.rms == Approx(std::sqrt(40.0 / 24)));
    CHECK(s.max == 6.0);
    CHECK(s.max_x == 1);
    CHECK(s.max_y == 0);
    CHECK(s.max_channel == 2);
    CHECK(s.pixels_over == 1);  // only the 6 passes 3
    CHECK(s.percent_over() == Approx(12.5));
    CHECK(difference_stats(ia, ib, 1.0).pixels_over == 2);

    // A mask hides the larger difference: only the 2 is left.
    std::vector<uint8_t> mask(8, 1);
    mask[1] = 0;
    const DifferenceStats masked = difference_stats(ia, ib, 1.0, mask);
    CHECK(masked.pixels == 7);
    CHECK(masked.max == 2.0);
    CHECK(masked.max_x == 3);
    CHECK(masked.max_y == 1);
    CHECK(masked.pixels_over == 1);

    const DifferenceStats same = difference_stats(ia, ia, 0.0);
    CHECK(same.max == 0.0);
    CHECK(same.max_x == -1);
    CHECK(same.pixels_over == 0);

    const std::vector<float> other(3 * 2 * 3, 0.0f);
    CHECK_THROWS_AS(difference_stats(ia, {3, 2, 3, other}, 1.0), std::invalid_argument);
    CHECK_THROWS_AS(difference_stats(ia, ib, 1.0, std::vector<uint8_t>(3, 1)),
                    std::invalid_argument);
}
