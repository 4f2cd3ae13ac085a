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
    // Background samples: the background's colour (black), nothing covering it.
    ColorImage color(4, 2, glm::vec4(0, 0, 0, 0));
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
    const glm::vec4 black(0, 0, 0, 1);
    resolve_supersampled({color, depth, nullptr, k, black}, {out_half, out_depth, nullptr, nullptr},
                         pool);
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
    resolve_supersampled({color, empty, nullptr, k, black}, {out_half, out_depth, nullptr, nullptr},
                         pool);
    CHECK(std::isinf(out_depth.at(0, 0)));
}

TEST_CASE("the resolve takes the background out for the alpha pass and averages lines",
          "[post][resolve]") {
    const float inf = std::numeric_limits<float>::infinity();
    const glm::vec4 blue(0, 0, 1, 1);
    // One output pixel of 2 x 2 samples: two on a red surface, one on the
    // blue background, one where a half-covering white line crosses the
    // background (its colour already over the background, its alpha 0.5).
    ColorImage color(2, 2, glm::vec4(0, 0, 1, 0));
    color.at(0, 0) = {1, 0, 0, 1};
    color.at(1, 0) = {1, 0, 0, 1};
    color.at(1, 1) = {0.5f, 0.5f, 1.0f, 0.5f};
    DepthImage depth(2, 2, inf);
    depth.at(0, 0) = depth.at(1, 0) = 4.0f;
    ColorImage lines(2, 2, glm::vec4(0));
    lines.at(1, 1) = {0.5f, 0.5f, 0.5f, 0.5f};  // premultiplied white at half coverage
    ThreadPool pool(1);
    HalfColorImage out(1, 1), alpha(1, 1), out_lines(1, 1);
    DepthImage out_depth(1, 1);
    resolve_supersampled({color, depth, &lines, 2, blue}, {out, out_depth, &alpha, &out_lines},
                         pool);
    const glm::vec4 c = to_float(out.at(0, 0)), a = to_float(alpha.at(0, 0)),
                    l = to_float(out_lines.at(0, 0));
    CHECK(c == glm::vec4(0.625f, 0.125f, 0.5f, 1.0f));  // opaque: the background is opaque
    // Over nothing: the two red samples and half a white line, premultiplied.
    CHECK(a.r == Approx(0.625f));
    CHECK(a.g == Approx(0.125f));
    CHECK(a.b == Approx(0.125f));  // the white line has blue in it too
    CHECK(a.a == Approx(0.625f));
    CHECK(l == glm::vec4(0.125f, 0.125f, 0.125f, 0.125f));
    CHECK(out_depth.at(0, 0) == 4.0f);
}
