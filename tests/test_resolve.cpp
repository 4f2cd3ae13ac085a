// Supersampling resolve: colour is the mean of each pixel's samples,
// depth the nearest sample's, +inf only where every sample missed.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "post/resolve.hpp"

using namespace facet;

TEST_CASE("supersampled frames resolve to mean colour and nearest depth", "[post][resolve]") {
    const float inf = std::numeric_limits<float>::infinity();
    const int k = 2;
    ColorImage color(4, 2, glm::vec4(0, 0, 0, 1));
    DepthImage depth(4, 2, inf);
    // Output pixel (0,0): one of four samples hits a red object at depth 3.
    color.at(1, 0) = {1, 0, 0, 1};
    depth.at(1, 0) = 3.0f;
    // Output pixel (1,0): samples at depths 5, 2, 7 and background.
    color.at(2, 0) = {0, 1, 0, 1};
    depth.at(2, 0) = 5.0f;
    color.at(3, 0) = {0, 1, 0, 1};
    depth.at(3, 0) = 2.0f;
    color.at(2, 1) = {0, 0, 1, 1};
    depth.at(2, 1) = 7.0f;

    ThreadPool pool(2);
    HalfColorImage out_half(2, 1);
    DepthImage out_depth(2, 1);
    resolve_supersampled(color, depth, k, out_half, out_depth, pool);
    const ColorImage out_color = to_float_image(out_half);
    CHECK(out_color.at(0, 0).r == Approx(0.25f));
    CHECK(out_color.at(0, 0).g == Approx(0.0f));
    CHECK(out_color.at(0, 0).a == Approx(1.0f));
    CHECK(out_depth.at(0, 0) == 3.0f);
    CHECK(out_color.at(1, 0).g == Approx(0.5f));
    CHECK(out_color.at(1, 0).b == Approx(0.25f));
    CHECK(out_depth.at(1, 0) == 2.0f);

    // All samples missing: the depth stays +inf.
    DepthImage empty(4, 2, inf);
    resolve_supersampled(color, empty, k, out_half, out_depth, pool);
    CHECK(std::isinf(out_depth.at(0, 0)));
}
