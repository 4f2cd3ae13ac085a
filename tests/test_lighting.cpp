// The lighting formulas (docs/styles.md) against values worked out by hand
// with the plain scalar formulas, for every lane of a batch.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "shade/lighting_batch.hpp"

using namespace facet;

namespace {

SurfaceBatch flat_up_surface(float ambient, float diffuse, float specular, float shininess) {
    SurfaceBatch s;
    for (int i = 0; i < simd::kLanes; ++i) {
        s.px[i] = static_cast<float>(i);  // each lane at (i, 0, 0)
        s.py[i] = s.pz[i] = 0;
        s.nx[i] = s.nz[i] = 0;
        s.ny[i] = 2.0f;  // not unit length: the batch normalises
        s.ambient[i] = ambient;
        s.diffuse[i] = diffuse;
        s.specular[i] = specular;
        s.shininess[i] = shininess;
    }
    return s;
}

}  // namespace

TEST_CASE("a directional light: ambient, Lambert and Blinn-Phong terms", "[shade][lighting]") {
    // Light from straight above, eye at 45 degrees above +X of lane 0.
    ShadeLight sun{false, {0, 1, 0}, {0, 0, 0}, {1.0f, 0.5f, 0.25f}};
    std::vector<ShadeLight> lights{sun};
    SurfaceBatch s = flat_up_surface(0.1f, 0.8f, 0.5f, 16);
    LightingBatch blinn = light_surface_batch(s, {1, 1, 0}, lights, Highlight::blinn);
    // n.l = 1, so diffuse = 0.1 + 0.8 * radiance.
    CHECK(blinn.dr[0] == Approx(0.9f));
    CHECK(blinn.dg[0] == Approx(0.5f));
    CHECK(blinn.db[0] == Approx(0.3f));
    // h = normalise(l + v) with v = (1,1,0)/sqrt2: n.h = cos(22.5 degrees).
    const double cos_half = std::cos(M_PI / 8);
    CHECK(blinn.sr[0] == Approx(0.5 * std::pow(cos_half, 16)).epsilon(1e-5));
    CHECK(blinn.sg[0] == Approx(0.25 * std::pow(cos_half, 16)).epsilon(1e-5));

    // Phong: r = reflect(-l) = (0,1,0), r.v = cos 45 degrees.
    LightingBatch phong = light_surface_batch(s, {1, 1, 0}, lights, Highlight::phong);
    CHECK(phong.sr[0] == Approx(0.5 * std::pow(std::cos(M_PI / 4), 16)).epsilon(1e-5));
    CHECK(phong.dr[0] == Approx(blinn.dr[0]));
}

TEST_CASE("a point light falls off with the square of the distance", "[shade][lighting]") {
    ShadeLight bulb{true, {0, 0, 0}, {0, 3, 0}, {9, 9, 9}};
    std::vector<ShadeLight> lights{bulb};
    SurfaceBatch s = flat_up_surface(0, 1, 0, 1);
    LightingBatch l = light_surface_batch(s, {0, 10, 0}, lights, Highlight::blinn);
    for (int i = 0; i < simd::kLanes; ++i) {
        // Lane i sits at (i, 0, 0): distance^2 = i^2 + 9, n.l = 3 / distance.
        const double d2 = i * i + 9.0;
        INFO("lane " << i);
        CHECK(l.dr[i] == Approx(9.0 / d2 * 3.0 / std::sqrt(d2)).epsilon(1e-5));
        CHECK(l.sr[i] == 0.0f);  // specular 0
    }
}

TEST_CASE("surfaces facing away from a light get none of it", "[shade][lighting]") {
    ShadeLight below{false, {0, -1, 0}, {0, 0, 0}, {1, 1, 1}};
    std::vector<ShadeLight> lights{below};
    SurfaceBatch s = flat_up_surface(0.2f, 0.8f, 0.5f, 8);
    LightingBatch l = light_surface_batch(s, {0, 5, 0}, lights, Highlight::blinn);
    CHECK(l.dr[3] == Approx(0.2f));  // ambient only
    CHECK(l.sr[3] == 0.0f);
}

// Relative error grows with |e log2 x| (about 1e-7 per unit of it), which only
// matters for results far below what 8- or 16-bit output can show.
TEST_CASE("the vector pow matches std::pow", "[shade][lighting]") {
    for (float x : {1e-6f, 0.01f, 0.3f, 0.5f, 0.77f, 0.999f, 1.0f})
        for (float e : {0.0f, 1.0f, 2.5f, 32.0f, 400.0f}) {
            simd::vf r = simd::vpow_unit(simd::splat(x), simd::splat(e));
            INFO(x << "^" << e);
            CHECK(r[0] == Approx(std::pow(x, e)).epsilon(2e-6).margin(1e-9));
        }
}
