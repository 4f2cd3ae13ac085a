// Spot, ambient, range and colour-temperature lights against values worked
// out by hand, through the same path as rendering: LightState (one frame's
// scene values) -> make_shade_lights -> the batched and the one-point lighting.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "anim/frame_state.hpp"
#include "render/frame_renderer.hpp"
#include "render/shade_lights.hpp"
#include "scene/color_temperature.hpp"
#include "scene_support.hpp"
#include "shade/light_sample.hpp"
#include "shade/lighting_batch.hpp"
#include "support.hpp"

using namespace facet;

namespace {

// Lane i at (xs[i], 0, 0) facing +Y, lit by diffuse only.
SurfaceBatch floor_lanes(const std::vector<float>& xs, float ambient = 0.0f) {
    SurfaceBatch s;
    for (int i = 0; i < simd::kLanes; ++i) {
        s.px[i] = xs[static_cast<size_t>(i) % xs.size()];
        s.py[i] = s.pz[i] = 0;
        s.nx[i] = s.nz[i] = 0;
        s.ny[i] = 1;
        s.ambient[i] = ambient;
        s.diffuse[i] = 1;
        s.specular[i] = 0;
        s.shininess[i] = 1;
    }
    return s;
}

LightState spot_state() {
    LightState l;
    l.type = LightType::spot;
    l.position = {0, 3, 0};
    l.direction = {0, -2, 0};  // travels down; need not be unit length
    l.inner_angle = 20;
    l.outer_angle = 30;
    l.intensity = 9;
    return l;
}

double smoothstep(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

}  // namespace

TEST_CASE("a spot light: full inside the inner cone, none outside the outer", "[shade][lights]") {
    const std::vector<ShadeLight> lights = make_shade_lights({spot_state()});
    REQUIRE(lights.size() == 1);
    CHECK(lights[0].is_point);
    CHECK(lights[0].is_spot);
    // Lanes at angles 0, 10, 25, 29, 31 and 60 degrees from the axis.
    const std::vector<double> degrees = {0, 10, 25, 29, 31, 60, 20, 30};
    std::vector<float> xs;
    for (double a : degrees) xs.push_back(static_cast<float>(3 * std::tan(a * M_PI / 180)));
    const LightingBatch l =
        light_surface_batch(floor_lanes(xs), {0, 5, 0}, lights, Highlight::blinn);
    for (size_t i = 0; i < degrees.size(); ++i) {
        const double a = degrees[i] * M_PI / 180;
        const double d2 = 9 / (std::cos(a) * std::cos(a));  // distance^2 to the light
        const double n_dot_l = std::cos(a);
        const double t = (std::cos(a) - std::cos(30 * M_PI / 180)) /
                         (std::cos(20 * M_PI / 180) - std::cos(30 * M_PI / 180));
        const double expected = 9 / d2 * n_dot_l * smoothstep(t);
        INFO(degrees[i] << " degrees");
        CHECK(l.dr[static_cast<int>(i)] == Approx(expected).margin(1e-6).epsilon(1e-5));
        CHECK(sample_light(lights[0], {xs[i], 0, 0}).radiance.x * n_dot_l ==
              Approx(expected).margin(1e-6).epsilon(1e-5));
    }
    // Worked by hand at 25 degrees: t = (cos 25 - cos 30) / (cos 20 - cos 30)
    // = 0.040283 / 0.073668 = 0.54682, smoothstep = 0.57003; at distance
    // 3 / cos 25, intensity 9 gives 9 cos^2 25 / 9 = 0.82139, times n.l = cos 25.
    CHECK(l.dr[2] == Approx(0.82139 * 0.906308 * 0.57003).epsilon(2e-4));
    CHECK(l.dr[1] == Approx(std::pow(std::cos(10 * M_PI / 180), 3)).epsilon(1e-5));
    CHECK(l.dr[4] == 0.0f);  // 31 degrees: outside the outer cone
    CHECK(l.dr[5] == 0.0f);
}

TEST_CASE("a spot with equal cone angles has a hard edge", "[shade][lights]") {
    LightState s = spot_state();
    s.inner_angle = s.outer_angle = 30;
    const std::vector<ShadeLight> lights = make_shade_lights({s});
    const float in = static_cast<float>(3 * std::tan(29.8 * M_PI / 180));
    const float out = static_cast<float>(3 * std::tan(30.2 * M_PI / 180));
    const LightingBatch l =
        light_surface_batch(floor_lanes({in, out}), {0, 5, 0}, lights, Highlight::blinn);
    CHECK(l.dr[0] > 0.5f);
    CHECK(l.dr[1] == 0.0f);
}

TEST_CASE("ambient lights: colour times intensity times ka, white 1 without any",
          "[shade][lights]") {
    LightState a;
    a.type = LightType::ambient;
    a.color = {0.5f, 0.25f, 1.0f};
    a.intensity = 2;
    LightState b = a;
    b.color = {0.1f, 0.1f, 0.1f};
    b.intensity = 1;
    LightState sun;
    sun.type = LightType::directional;
    sun.direction = {0, -1, 0};
    sun.intensity = 0.5f;
    // Ambient lights go last, so lights[0] is the key light of the stylised models.
    const std::vector<ShadeLight> lights = make_shade_lights({a, sun, b});
    REQUIRE(lights.size() == 3);
    CHECK(!lights[0].is_ambient);
    CHECK(lights[1].is_ambient);
    CHECK(lights[2].is_ambient);
    CHECK(sample_light(lights[1], {0, 0, 0}).radiance == glm::vec3(0.0f));

    const LightingBatch l =
        light_surface_batch(floor_lanes({0}, 0.2f), {0, 5, 0}, lights, Highlight::blinn);
    // ka * (a + b) + kd * n.l * sun = 0.2 * (1.1, 0.6, 2.1) + 0.5
    CHECK(l.dr[0] == Approx(0.2 * 1.1 + 0.5));
    CHECK(l.dg[0] == Approx(0.2 * 0.6 + 0.5));
    CHECK(l.db[0] == Approx(0.2 * 2.1 + 0.5));
    CHECK(l.sr[0] == 0.0f);

    // No ambient light: the material's ka alone (white ambient of 1).
    const std::vector<ShadeLight> none = make_shade_lights({sun});
    const LightingBatch m =
        light_surface_batch(floor_lanes({0}, 0.2f), {0, 5, 0}, none, Highlight::blinn);
    CHECK(m.dr[0] == Approx(0.7));
    // An ambient light of intensity 0 turns ambient off.
    LightState dark = a;
    dark.intensity = 0;
    const LightingBatch o = light_surface_batch(floor_lanes({0}, 0.2f), {0, 5, 0},
                                                make_shade_lights({dark}), Highlight::blinn);
    CHECK(o.dr[0] == 0.0f);
}

TEST_CASE("a point light's range fades it smoothly to zero", "[shade][lights]") {
    LightState p;
    p.type = LightType::point;
    p.position = {0, 1, 0};
    p.intensity = 1;
    p.range = 4;
    const std::vector<ShadeLight> lights = make_shade_lights({p});
    REQUIRE(lights[0].inv_range == 0.25f);
    // Window (1 - (d/4)^4)^2 on top of 1/d^2; lanes at d = 1, 2, 3, 4, 5.
    std::vector<float> xs = {0, std::sqrt(3.0f), std::sqrt(8.0f), std::sqrt(15.0f),
                             std::sqrt(24.0f)};
    const LightingBatch l =
        light_surface_batch(floor_lanes(xs), {0, 5, 0}, lights, Highlight::blinn);
    // d = 2: (1 - 1/16)^2 = 0.87890625, / 4, times n.l = 1/2.
    CHECK(l.dr[1] == Approx(0.87890625 / 4 * 0.5).epsilon(1e-5));
    for (int i = 0; i < 4; ++i) {
        const double d = i + 1;
        const double window = std::pow(1 - std::pow(d / 4, 4), 2);
        INFO("d = " << d);
        CHECK(l.dr[i] == Approx(window / (d * d) * (1 / d)).margin(1e-7).epsilon(1e-5));
    }
    CHECK(l.dr[3] == 0.0f);                             // at the range
    CHECK(l.dr[4] == 0.0f);                             // beyond it
    CHECK(range_window(3.99f * 3.99f, 0.25f) < 1e-4f);  // reaches zero without a step

    // Without a range, plain inverse square.
    p.range = 0;
    const LightingBatch n =
        light_surface_batch(floor_lanes(xs), {0, 5, 0}, make_shade_lights({p}), Highlight::blinn);
    CHECK(n.dr[1] == Approx(0.25 * 0.5));
}

TEST_CASE("colour temperatures: 6500 K is near white, 2000 K orange", "[shade][lights]") {
    const LinearRgb d65ish = kelvin_to_linear_srgb(6500);
    CHECK(d65ish.r == Approx(1.0).margin(0.07));
    CHECK(d65ish.g == Approx(1.0).margin(0.07));
    CHECK(d65ish.b == Approx(1.0).margin(0.07));
    // 2000 K, worked by hand through the same fit: x = 0.52690, y = 0.41327,
    // linear sRGB (2.5222, 0.6462, 0.0200) scaled to (1, 0.2562, 0.0079).
    const LinearRgb candle = kelvin_to_linear_srgb(2000);
    CHECK(candle.r == Approx(1.0));
    CHECK(candle.g == Approx(0.2562).margin(0.002));
    CHECK(candle.b == Approx(0.0079).margin(0.002));
    CHECK(candle.r > candle.g);
    CHECK(candle.g > candle.b);
    // Blue against red grows with the temperature; 10000 K is bluish.
    double last = -1;
    for (double k : {1667.0, 2500.0, 3200.0, 4000.0, 5600.0, 6500.0, 10000.0, 25000.0}) {
        const LinearRgb c = kelvin_to_linear_srgb(k);
        INFO(k << " K");
        CHECK(std::max({c.r, c.g, c.b}) == Approx(1.0));
        CHECK(c.b / c.r > last);
        last = c.b / c.r;
    }
    const LinearRgb sky = kelvin_to_linear_srgb(10000);
    CHECK(sky.b > sky.r);
    // Outside the fit's range the ends are used.
    const LinearRgb low = kelvin_to_linear_srgb(1000), end = kelvin_to_linear_srgb(1667);
    CHECK(low.g == end.g);
}

TEST_CASE("light keys: spot, ambient, kelvin, range and shadows are read", "[scene][lights]") {
    test::TempDir dir("lights");
    const std::string path = test::write_text(dir.file("s.yaml"), R"(
output: { frames: "1-10" }
lights:
  - { type: spot, position: [0, 4, 0], direction: [0, -1, 0], inner_angle: 15, outer_angle: 25,
      range: 12, color: { kelvin: 3200 }, intensity: 20, shadows: true }
  - { type: ambient, color: [0.1, 0.2, 0.3], intensity: 0.5 }
  - type: point
    position: { keys: { 1: [0, 2, 0], 10: [4, 2, 0] } }
    color: { kelvin: { keys: { 1: 2000, 10: 8000 } } }
    shadow_softness: 2
  - { type: directional, direction: [0, -1, 0], shadows: false, shadow_resolution: 256 }
  - type: spot
    position: [0, 4, 0]
    direction: [0, -1, 0]
    inner_angle: { keys: { 1: 10, 10: 50 } }
    outer_angle: 30
objects:
  - { primitive: cube, cast_shadows: false }
  - { primitive: plane, receive_shadows: false, material: { ka: 0.3, kd: 0.6, ks: 0.1 } }
)");
    const SceneDesc scene = test::load(path);
    REQUIRE(scene.lights.size() == 5);
    const LightDesc& spot = scene.lights[0];
    CHECK(spot.type == LightType::spot);
    CHECK(spot.inner_angle.value == 15);
    CHECK(spot.outer_angle.value == 25);
    REQUIRE(spot.range);
    CHECK(spot.range->value == 12);
    REQUIRE(spot.kelvin);
    CHECK(spot.kelvin->value == 3200);
    CHECK(spot.shadows);
    CHECK(spot.shadow_resolution == 1024);
    CHECK(scene.lights[1].type == LightType::ambient);
    CHECK(!scene.lights[1].shadows);
    // Another shadow key turns shadows on; `shadows: false` keeps them off.
    CHECK(scene.lights[2].shadows);
    CHECK(scene.lights[2].shadow_resolution == 512);
    CHECK(!scene.lights[3].shadows);
    CHECK(scene.lights[3].shadow_resolution == 256);
    CHECK(!scene.objects[0].cast_shadows);
    CHECK(scene.objects[0].receive_shadows);
    CHECK(scene.objects[1].cast_shadows);
    CHECK(!scene.objects[1].receive_shadows);
    REQUIRE(scene.objects[1].material.ambient);
    CHECK(scene.objects[1].material.ambient->value == Approx(0.3f));
    CHECK(scene.objects[1].material.diffuse->value == Approx(0.6f));
    CHECK(scene.objects[1].material.specular->value == Approx(0.1f));

    // Every value is evaluated per frame; kelvin keys move the colour.
    const FrameState first = evaluate_frame(scene, {}, 1);
    const FrameState last = evaluate_frame(scene, {}, 10);
    const LinearRgb warm = kelvin_to_linear_srgb(3200);
    CHECK(first.lights[0].color.z == Approx(warm.b));
    CHECK(first.lights[0].range == 12);
    CHECK(first.lights[2].color.z < last.lights[2].color.z);
    CHECK(last.lights[2].position.x == Approx(4));
    CHECK(first.lights[2].shadow_softness == 2);
    // Keyed cone angles that cross keep inner <= outer.
    CHECK(first.lights[4].inner_angle == Approx(10));
    CHECK(last.lights[4].inner_angle == Approx(30));
}
