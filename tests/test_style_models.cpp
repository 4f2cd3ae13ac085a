// The stylised shading models against values worked out by hand: the
// seed-000 palette method, Gooch 1998, toon bands and ramps, toon highlight
// and rim, and the wireframe edge distances.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "shade/gooch_style.hpp"
#include "shade/light_sample.hpp"
#include "shade/palette_style.hpp"
#include "shade/toon_style.hpp"
#include "shade/wireframe.hpp"

using namespace facet;

namespace {

void check_color(const glm::vec3& got, const glm::vec3& want, double eps = 1e-5) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", "
                 << want.y << ", " << want.z << ")");
    CHECK(got.x == Approx(want.x).margin(eps));
    CHECK(got.y == Approx(want.y).margin(eps));
    CHECK(got.z == Approx(want.z).margin(eps));
}

PaletteStyle hand_palette(int cels) {
    PaletteStyle s;
    s.shadow_color = {0.0f, 0.0f, 0.4f};
    s.lit_color = {0.4f, 0.4f, 0.0f};
    s.alpha = 0.2f;
    s.beta = 0.6f;
    s.ambient = 0.2f;
    s.cels = cels;
    return s;
}

const glm::vec3 kOrange{1.0f, 0.5f, 0.0f};

}  // namespace

TEST_CASE("seed palette: ambient plus the cool-to-warm blend, unquantised", "[style][palette]") {
    const PaletteStyle s = hand_palette(0);
    // cool = (0,0,.4) + .2 k = (.2,.1,.4); warm = (.4,.4,0) + .6 k = (1,.7,0);
    // ambient = .2 k = (.2,.1,0).
    check_color(seed_palette(s, kOrange, 0.0f).color, {0.8f, 0.5f, 0.2f});   // t = 1/2
    check_color(seed_palette(s, kOrange, 1.0f).color, {1.2f, 0.8f, 0.0f});   // t = 1: warm
    check_color(seed_palette(s, kOrange, -1.0f).color, {0.4f, 0.2f, 0.4f});  // t = 0: cool
    // n·l beyond [-1, 1] (unnormalised input) is clamped, not extrapolated.
    check_color(seed_palette(s, kOrange, 3.0f).color, {1.2f, 0.8f, 0.0f});
}

TEST_CASE("seed palette: cels give the seed's c' = c·q", "[style][palette]") {
    // c = (.8,.5,.2), |c| = sqrt(.93) = .96437: 4 cels round 3.857 to 4, so
    // q = 1 (the seed's truncation would give 3/4) and c' = c.
    const PaletteShading p = seed_palette(hand_palette(4), kOrange, 0.0f);
    check_color(p.color, {0.8f, 0.5f, 0.2f});
    CHECK(p.tone == Approx(1.0f / std::sqrt(3.0f)));
    // t = 0: c = (.4,.2,.4), |c| = .6: 4 cels give q = 2/4 (2.4 rounds to 2).
    const PaletteShading cool = seed_palette(hand_palette(4), kOrange, -1.0f);
    check_color(cool.color, {0.2f, 0.1f, 0.2f});
    CHECK(cool.tone == Approx(0.5f / std::sqrt(3.0f)));

    const std::vector<glm::vec3> colors{
        {0.8f, 0.5f, 0.2f}, {0.13f, 0.02f, 0.4f}, {1.7f, 0.9f, 1.1f}, {0.05f, 0.05f, 0.05f}};
    for (int cels : {1, 3, 4, 7}) {
        for (const glm::vec3& c : colors) {
            const float q = std::floor(color_length(c) * cels + 0.5f) / cels;
            INFO("cels " << cels << ", colour " << c.x << " " << c.y << " " << c.z);
            check_color(quantise_cels(c, cels), c * q, 1e-6);
            CHECK(cel_level(c, cels) == Approx(q).margin(1e-6));
        }
    }
    check_color(quantise_cels(glm::vec3(0.0f), 4), glm::vec3(0.0f));
    check_color(quantise_cels({0.3f, 0.2f, 0.1f}, 0), {0.3f, 0.2f, 0.1f});
}

TEST_CASE("seed palette: keep_hue cels snap |c| to k/N and keep the hue", "[style][palette]") {
    PaletteStyle s = hand_palette(4);
    s.cels_keep_hue = true;
    const PaletteShading p = seed_palette(s, kOrange, 0.0f);
    const float len = std::sqrt(0.93f);
    check_color(p.color, glm::vec3(0.8f, 0.5f, 0.2f) / len);
    CHECK(color_length(p.color) == Approx(1.0f));
    CHECK(p.tone == Approx(1.0f / std::sqrt(3.0f)));  // the same tone in both modes

    const std::vector<glm::vec3> colors{
        {0.8f, 0.5f, 0.2f}, {0.13f, 0.02f, 0.4f}, {1.7f, 0.9f, 1.1f}, {0.05f, 0.05f, 0.05f}};
    for (int cels : {1, 3, 4, 7}) {
        for (const glm::vec3& c : colors) {
            const glm::vec3 q = quantise_cels(c, cels, true);
            const float steps = std::floor(color_length(c) * cels + 0.5f);
            INFO("cels " << cels << ", colour " << c.x << " " << c.y << " " << c.z);
            CHECK(color_length(q) == Approx(steps / cels).margin(1e-6));
            if (steps > 0) {
                CHECK(q.x / q.y == Approx(c.x / c.y));  // r:g:b unchanged
                CHECK(q.z / q.y == Approx(c.z / c.y));
            }
        }
    }
    check_color(quantise_cels(glm::vec3(0.0f), 4, true), glm::vec3(0.0f));  // no division by zero
}

TEST_CASE("seed palette: hatching tone, ink and highlight", "[style][palette]") {
    PaletteStyle s = hand_palette(4);
    s.hatch_below = 0.5f;
    CHECK(palette_hatch_tone(s, 0.25f) == Approx(0.5f));  // the seed's dense-stroke threshold
    CHECK(palette_hatch_tone(s, 0.0f) == 0.0f);
    CHECK(palette_hatch_tone(s, 0.5f) == 1.0f);  // at and above 0.5: no strokes
    CHECK(palette_hatch_tone(s, 0.9f) == 1.0f);
    s.hatch_ink = 0.25f;
    check_color(palette_ink(s, kOrange), {0.25f, 0.125f, 0.0f});
    check_color(apply_hatching({1, 1, 1}, {0.25f, 0, 0}, 0.5f), {0.625f, 0.5f, 0.5f});
    check_color(apply_hatching({1, 1, 1}, {0.25f, 0, 0}, 0.0f), {1, 1, 1});
    // The seed's additive strokes: ink x coverage added, nothing where there is no stroke.
    check_color(add_hatching({0.5f, 0.5f, 0.5f}, {0.25f, 0.125f, 0}, 0.5f),
                {0.625f, 0.5625f, 0.5f});
    check_color(add_hatching({0.5f, 0.5f, 0.5f}, {0.25f, 0.125f, 0}, 0.0f), {0.5f, 0.5f, 0.5f});

    s.shininess = 16;
    s.specular = 0.5f;
    const glm::vec3 n{0, 1, 0};
    const LightSample sun{{0, 1, 0}, {1.0f, 0.5f, 1.0f}};
    // Eye along n: h = n, highlight = .5 k radiance.
    check_color(seed_specular(s, kOrange, n, {0, 1, 0}, sun), {0.5f, 0.125f, 0.0f});
    // Eye at 45 degrees: n·h = cos 22.5 degrees.
    const glm::vec3 v = glm::vec3(1, 1, 0) / std::sqrt(2.0f);
    const double power = std::pow(std::cos(M_PI / 8), 16);
    check_color(seed_specular(s, kOrange, n, v, sun), {0.5 * power, 0.125 * power, 0.0}, 1e-6);
    // A light behind the surface gives no highlight.
    check_color(seed_specular(s, kOrange, n, v, {{0, -1, 0}, {1, 1, 1}}), glm::vec3(0.0f));
}

TEST_CASE("light samples: directional as given, point lights fall off", "[style]") {
    const ShadeLight sun{false, {0, 1, 0}, {0, 0, 0}, {1, 2, 3}};
    const LightSample a = sample_light(sun, {5, 5, 5});
    check_color(a.to_light, {0, 1, 0});
    check_color(a.radiance, {1, 2, 3});
    const ShadeLight bulb{true, {}, {0, 4, 3}, {25, 25, 25}};
    const LightSample b = sample_light(bulb, {0, 0, 0});
    check_color(b.to_light, {0, 0.8f, 0.6f});
    check_color(b.radiance, {1, 1, 1});  // 25 / 5^2
    check_color(sample_light(bulb, {0, 4, 3}).radiance, glm::vec3(0.0f));
}

TEST_CASE("Gooch: cool at n·l = -1, warm at 1, their mean at 0", "[style][gooch]") {
    // The renderer's Gooch diffuse: the palette blend with the paper's
    // b = y = .4, alpha = .2, beta = .6, no ambient and no cels.
    PaletteStyle g = hand_palette(0);
    g.ambient = 0;
    const glm::vec3 kd(0.5f);
    // cool = (0,0,.4) + .2 kd = (.1,.1,.5); warm = (.4,.4,0) + .6 kd = (.7,.7,.3).
    check_color(seed_palette(g, kd, -1.0f).color, {0.1f, 0.1f, 0.5f});
    check_color(seed_palette(g, kd, 1.0f).color, {0.7f, 0.7f, 0.3f});
    check_color(seed_palette(g, kd, 0.0f).color, {0.4f, 0.4f, 0.4f});
    check_color(seed_palette(g, kd, 0.5f).color, {0.55f, 0.55f, 0.35f});  // t = 3/4

    // Phong highlight: r = reflect(l) = n; eye along n gives 1, at 45 degrees cos^s 45.
    GoochStyle shiny;
    shiny.shininess = 8;
    const glm::vec3 n{0, 1, 0};
    const LightSample light{{0, 1, 0}, {1, 1, 1}};
    check_color(gooch_highlight(shiny, n, {0, 1, 0}, light), {1, 1, 1});
    const double power = std::pow(std::cos(M_PI / 4), 8);
    check_color(gooch_highlight(shiny, n, glm::vec3(1, 1, 0) / std::sqrt(2.0f), light),
                glm::vec3(static_cast<float>(power)), 1e-6);
    check_color(gooch_highlight(shiny, n, {0, 1, 0}, {{0, -1, 0}, {1, 1, 1}}), glm::vec3(0.0f));
}

TEST_CASE("toon bands: thresholds select the band, softness blends at the edge", "[style][toon]") {
    ToonStyle t;  // bands -1: .35, 0: .7, .5: 1
    const glm::vec3 white(1.0f);
    check_color(toon_diffuse(t, white, -0.5f), glm::vec3(0.35f));
    check_color(toon_diffuse(t, white, -2.0f), glm::vec3(0.35f));  // below the first threshold
    check_color(toon_diffuse(t, white, 0.0f), glm::vec3(0.7f));    // a threshold starts its band
    check_color(toon_diffuse(t, white, 0.49f), glm::vec3(0.7f));
    check_color(toon_diffuse(t, white, 0.5f), glm::vec3(1.0f));
    check_color(toon_diffuse(t, kOrange, 0.2f), kOrange * 0.7f);  // bands scale the albedo

    t.band_softness = 0.2f;  // edges over [threshold - .1, threshold + .1]
    check_color(toon_diffuse(t, white, 0.4f), glm::vec3(0.7f));
    check_color(toon_diffuse(t, white, 0.5f), glm::vec3(0.85f));  // smoothstep(.5) = .5
    check_color(toon_diffuse(t, white, 0.6f), glm::vec3(1.0f));
    // smoothstep at a quarter of the edge: 3/16 - 2/64 = 0.15625.
    check_color(toon_diffuse(t, white, 0.45f), glm::vec3(0.7f + 0.3f * 0.15625f));

    ToonStyle colours;
    colours.multiply_albedo = false;
    colours.bands = {{-1.0f, {0.1f, 0.1f, 0.3f}}, {0.3f, {1.0f, 0.8f, 0.6f}}};
    check_color(toon_diffuse(colours, kOrange, 0.0f), {0.1f, 0.1f, 0.3f});
    check_color(toon_diffuse(colours, kOrange, 0.9f), {1.0f, 0.8f, 0.6f});
}

TEST_CASE("toon ramp: linear between stops, constant beyond", "[style][toon]") {
    ToonStyle t;
    t.mode = ToonMode::ramp;
    t.multiply_albedo = false;
    t.bands = {{0.0f, {0, 0, 0}}, {0.5f, {1, 0, 0}}, {1.0f, {1, 1, 1}}};
    check_color(toon_diffuse(t, kOrange, -0.7f), {0, 0, 0});
    check_color(toon_diffuse(t, kOrange, 0.25f), {0.5f, 0, 0});
    check_color(toon_diffuse(t, kOrange, 0.75f), {1, 0.5f, 0.5f});
    check_color(toon_diffuse(t, kOrange, 1.0f), {1, 1, 1});
    check_color(toon_diffuse(t, kOrange, 2.0f), {1, 1, 1});
}

TEST_CASE("toon highlight is hard and thresholded, rim light on grazing normals", "[style][toon]") {
    ToonStyle t;
    t.shininess = 32;
    t.specular_threshold = 0.5f;
    t.specular_color = {1, 1, 0.5f};
    const glm::vec3 n{0, 1, 0};
    const LightSample light{{0, 1, 0}, {2, 2, 2}};
    check_color(toon_specular(t, n, {0, 1, 0}, light), {2, 2, 1});  // n·h = 1: fully on
    // Eye at 45 degrees: (cos 22.5)^32 = 0.079 < 0.5: off, not dimmed.
    check_color(toon_specular(t, n, glm::vec3(1, 1, 0) / std::sqrt(2.0f), light), glm::vec3(0.0f));
    // Eye at 10 degrees: (cos 5)^32 = 0.885: fully on.
    const float a = 10.0f * static_cast<float>(M_PI) / 180.0f;
    check_color(toon_specular(t, n, {std::sin(a), std::cos(a), 0}, light), {2, 2, 1});

    t.rim_color = {0.2f, 0.4f, 0.6f};
    t.rim_power = 2;
    t.rim_threshold = 0.5f;
    // n·v = 0.2: (0.8)^2 = 0.64 >= 0.5 on; n·v = 0.4: 0.36 off; facing: off.
    auto eye_at = [](float n_dot_v) {
        return glm::vec3(std::sqrt(1 - n_dot_v * n_dot_v), n_dot_v, 0);
    };
    check_color(toon_rim(t, n, eye_at(0.2f)), {0.2f, 0.4f, 0.6f});
    check_color(toon_rim(t, n, eye_at(0.4f)), glm::vec3(0.0f));
    check_color(toon_rim(t, n, eye_at(1.0f)), glm::vec3(0.0f));
    t.rim_color = glm::vec3(0.0f);  // the default: no rim
    check_color(toon_rim(t, n, eye_at(0.0f)), glm::vec3(0.0f));
}

TEST_CASE("wireframe: distances to the edges and the line coverage", "[style][wireframe]") {
    const glm::vec2 a{0, 0}, b{10, 0}, c{0, 10};
    // p = (1, 3): 6/sqrt 2 from the hypotenuse (opposite a), 1 from x = 0
    // (opposite b), 3 from y = 0 (opposite c).
    const glm::vec3 d = edge_distances({1, 3}, a, b, c);
    CHECK(d.x == Approx(6.0 / std::sqrt(2.0)));
    CHECK(d.y == Approx(1.0f));
    CHECK(d.z == Approx(3.0f));
    // The same from screen-linear barycentrics b = (1 - x/10 - y/10, x/10, y/10).
    const glm::vec3 from_bary =
        edge_distances(glm::vec3(0.6f, 0.1f, 0.3f), {-0.1f, 0.1f, 0.0f}, {-0.1f, 0.0f, 0.1f});
    CHECK(from_bary.x == Approx(d.x));
    CHECK(from_bary.y == Approx(d.y));
    CHECK(from_bary.z == Approx(d.z));

    CHECK(wire_coverage({5, 0.5f, 5}, 1.0f) == Approx(0.5f));  // half of a 1 px line
    CHECK(wire_coverage({5, 0.5f, 5}, 2.0f) == Approx(1.0f));
    CHECK(wire_coverage({5, 1.0f, 5}, 1.0f) == Approx(0.0f));
    CHECK(wire_coverage({5, 1.0f, 5}, 2.5f) == Approx(0.75f));
    CHECK(wire_coverage({5, 0.5f, 5}, 2.0f, 0b101) == Approx(0.0f));  // edge 1 hidden

    // Across an edge shared by two triangles, the pixels on both sides add
    // up to the width: a row of pixel centres 0.5, 1.5, ... from the edge.
    for (float width : {1.0f, 2.0f, 3.0f, 4.5f}) {
        float total = 0.0f;
        for (int i = 0; i < 10; ++i)
            total += 2.0f * wire_coverage({100, 0.5f + static_cast<float>(i), 100}, width);
        CHECK(total == Approx(width));
    }
}
