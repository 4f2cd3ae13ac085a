// Keyframe tracks (src/anim/track.cpp, src/scene/track_parser.cpp): every
// interpolation mode against values worked out by hand, extrapolation,
// keys in seconds, clamping to a field's range, rotations without flips,
// and the errors a malformed track gives.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "anim/frame_state.hpp"
#include "anim/track.hpp"
#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using Catch::Contains;
using facet::Animated;
using facet::FrameTime;
using facet::Track;
using facet::TrackExtrapolation;
using facet::TrackInterpolation;
using namespace facet::test;

namespace {

Track scalar_track(std::vector<double> times, std::vector<double> values,
                   TrackInterpolation mode = TrackInterpolation::linear) {
    Track t;
    t.times = std::move(times);
    for (double v : values) t.values.emplace_back(v, 0, 0, 0);
    t.interpolation = mode;
    return t;
}

double at(const Track& t, double time) {
    return facet::evaluate_track(t, time).x;
}

// A rotation track of Euler keys (degrees).
Animated<glm::vec3> rotation_track(std::vector<double> times, std::vector<glm::dvec3> degrees,
                                   TrackInterpolation mode = TrackInterpolation::linear,
                                   facet::RotationPath path = facet::RotationPath::automatic) {
    auto t = std::make_shared<Track>();
    t->times = std::move(times);
    for (const auto& d : degrees) t->values.emplace_back(d, 0);
    t->components = 3;
    t->interpolation = mode;
    t->rotation = path;
    Animated<glm::vec3> a;
    a.value = glm::vec3(degrees.front());
    a.track = t;
    return a;
}

glm::dquat rotation_at(const Animated<glm::vec3>& a, double frame) {
    return facet::evaluate_rotation(a, FrameTime{frame, 0});
}

// Rotations this close (in degrees) are equal: acos near 1 loses about 1e-6.
constexpr double kTiny = 1e-4;

// The angle in degrees of the rotation taking a to b (q and -q are one rotation).
double angle_between(const glm::dquat& a, const glm::dquat& b) {
    const double d = std::min(1.0, std::abs(glm::dot(a, b)));
    return glm::degrees(2 * std::acos(d));
}

glm::dquat about_y(double degrees) {
    return facet::euler_to_quat({0, degrees, 0});
}

facet::SceneDesc load_text(const std::string& text) {
    TempDir dir("tracks");
    return load(write_text(dir.file("anim.yaml"), text));
}

}  // namespace

// ---------------------------------------------------------------------------
// Interpolation modes

TEST_CASE("step holds each key until the next one", "[anim]") {
    Track t = scalar_track({1, 5, 9}, {0, 10, -2}, TrackInterpolation::step);
    CHECK(at(t, 1) == 0);
    CHECK(at(t, 3) == 0);
    CHECK(at(t, 4.999) == 0);
    CHECK(at(t, 5) == 10);  // a key's own frame shows that key
    CHECK(at(t, 8.9) == 10);
    CHECK(at(t, 9) == -2);
}

TEST_CASE("linear interpolates each segment in a straight line", "[anim]") {
    Track t = scalar_track({1, 5, 9}, {0, 10, -2});
    CHECK(at(t, 3) == Approx(5));  // 0 + 10 * 2/4
    CHECK(at(t, 7) == Approx(4));  // 10 - 12 * 2/4
    CHECK(at(t, 8) == Approx(1));  // 10 - 12 * 3/4
    CHECK(at(t, 5) == Approx(10));
}

TEST_CASE("smooth is Catmull-Rom through evenly spaced keys", "[anim]") {
    // Uniform Catmull-Rom on the segment P1..P2:
    //   0.5 * (2P1 + (-P0 + P2) s + (2P0 - 5P1 + 4P2 - P3) s^2 + (-P0 + 3P1 - 3P2 + P3) s^3)
    // Keys 0, 1, 3, 2 every 10 frames (frames 1, 11, 21, 31).
    Track t = scalar_track({1, 11, 21, 31}, {0, 1, 3, 2}, TrackInterpolation::smooth);
    // Middle segment, P = 0, 1, 3, 2:
    //   s = 0.5:  0.5 * (2 + 3 * 0.5 + 5 * 0.25 - 4 * 0.125) = 0.5 * 4.25 = 2.125
    //   s = 0.25: 0.5 * (2 + 3 * 0.25 + 5 / 16 - 4 / 64) = 0.5 * 3 = 1.5
    CHECK(at(t, 16) == Approx(2.125));
    CHECK(at(t, 13.5) == Approx(1.5));
    // Through the keys themselves.
    CHECK(at(t, 11) == Approx(1));
    CHECK(at(t, 21) == Approx(3));
    // First segment: the missing neighbour is mirrored, P_-1 = 2 * 0 - 1 = -1;
    // P = -1, 0, 1, 3 at s = 0.5: 0.5 * (0 + 2 * 0.5 - 1 * 0.25 + 1 * 0.125) = 0.4375
    CHECK(at(t, 6) == Approx(0.4375));
    // Last segment: P3 = 2 * 2 - 3 = 1; P = 1, 3, 2, 1 at s = 0.5:
    //   0.5 * (6 + 1 * 0.5 - 6 * 0.25 + 3 * 0.125) = 0.5 * 5.375 = 2.6875
    CHECK(at(t, 26) == Approx(2.6875));
    // Linear would give 2 in the middle segment: smooth really differs.
    CHECK(std::abs(at(t, 16) - 2) > 0.1);
}

TEST_CASE("smooth with unevenly spaced keys uses the key times as knots", "[anim]") {
    // Keys (t, P): (0, 0), (1, 1), (3, 3), (4, 2). With key times as knots
    // (Barry-Goldman), the segment 1..3 is the cubic Hermite curve with tangents
    //   m_i = (P_i - P_i-1)/(t_i - t_i-1) * (t_i+1 - t_i)/(t_i+1 - t_i-1)
    //       + (P_i+1 - P_i)/(t_i+1 - t_i) * (t_i - t_i-1)/(t_i+1 - t_i-1)
    //   m1 = 1 * 2/3 + 1 * 1/3 = 1,  m2 = 1 * 1/3 + (-1) * 2/3 = -1/3,  h = 2.
    // P(s) = h00 P1 + h10 h m1 + h01 P2 + h11 h m2 with
    //   h00 = 2s^3 - 3s^2 + 1, h10 = s^3 - 2s^2 + s, h01 = -2s^3 + 3s^2, h11 = s^3 - s^2:
    //   s = 0.5:  0.5 + 0.125*2 + 1.5 + (-0.125)*2*(-1/3)            = 7/3
    //   s = 0.25: 0.84375 + 0.140625*2 + 0.15625*3 - 0.046875*2*(-1/3) = 1.625
    //   s = 0.75: 0.15625 + 0.046875*2 + 0.84375*3 - 0.140625*2*(-1/3) = 2.875
    Track t = scalar_track({0, 1, 3, 4}, {0, 1, 3, 2}, TrackInterpolation::smooth);
    CHECK(at(t, 2) == Approx(7.0 / 3.0));
    CHECK(at(t, 1.5) == Approx(1.625));
    CHECK(at(t, 2.5) == Approx(2.875));
    CHECK(at(t, 3) == Approx(3));
    // The uniform formula (keys taken as evenly spaced) would give 2.125.
    CHECK(std::abs(at(t, 2) - 2.125) > 0.1);
}

TEST_CASE("eased modes follow the CSS cubic-bezier timing curves", "[anim]") {
    // A timing curve is x(u) = 3(1-u)^2 u x1 + 3(1-u) u^2 x2 + u^3 and the same
    // for y, so ease(x(u)) must be y(u) for any u.
    auto bez = [](double p1, double p2, double u) {
        return 3 * (1 - u) * (1 - u) * u * p1 + 3 * (1 - u) * u * u * p2 + u * u * u;
    };
    struct Mode {
        TrackInterpolation mode;
        glm::dvec4 c;
    };
    const glm::dvec4 unused{0.9, 0.9, 0.9, 0.9};
    for (const Mode& m : {Mode{TrackInterpolation::ease_in, {0.42, 0, 1, 1}},
                          Mode{TrackInterpolation::ease_out, {0, 0, 0.58, 1}},
                          Mode{TrackInterpolation::ease_in_out, {0.42, 0, 0.58, 1}}}) {
        for (double u : {0.1, 0.25, 0.5, 0.75, 0.9}) {
            INFO("mode " << static_cast<int>(m.mode) << " u " << u);
            CHECK(facet::ease(m.mode, unused, bez(m.c.x, m.c.z, u)) ==
                  Approx(bez(m.c.y, m.c.w, u)).margin(1e-9));
        }
        CHECK(facet::ease(m.mode, unused, 0) == 0);
        CHECK(facet::ease(m.mode, unused, 1) == 1);
    }
    // At s = 0.5 (solving x(u) = 0.5 by hand, to 4 places): ease_in 0.3154,
    // ease_out 0.6846 (= 1 - ease_in by symmetry), ease_in_out exactly 0.5.
    CHECK(facet::ease(TrackInterpolation::ease_in, unused, 0.5) == Approx(0.3154).margin(1e-4));
    CHECK(facet::ease(TrackInterpolation::ease_out, unused, 0.5) == Approx(0.6846).margin(1e-4));
    CHECK(facet::ease(TrackInterpolation::ease_in_out, unused, 0.5) == Approx(0.5).margin(1e-9));
    // u = 0.25 on ease_in: x = 3*0.5625*0.25*0.42 + 3*0.75*0.0625 + 0.015625 = 0.3334375,
    // y = 3*0.75*0.0625 + 0.015625 = 0.15625.
    CHECK(facet::ease(TrackInterpolation::ease_in, unused, 0.3334375) ==
          Approx(0.15625).margin(1e-9));

    // User handles, y outside [0, 1] allowed (overshoot), checked the same way.
    const glm::dvec4 handles{0.3, -0.4, 0.6, 1.5};
    for (double u : {0.2, 0.5, 0.8})
        CHECK(facet::ease(TrackInterpolation::bezier, handles, bez(0.3, 0.6, u)) ==
              Approx(bez(-0.4, 1.5, u)).margin(1e-9));
}

TEST_CASE("bezier (0, 0, 1, 1) is linear, and eased tracks ease each segment", "[anim]") {
    for (double s = 0; s <= 1.0; s += 0.05)
        CHECK(facet::ease(TrackInterpolation::bezier, {0, 0, 1, 1}, s) == Approx(s).margin(1e-9));
    Track t = scalar_track({1, 11, 21}, {0, 10, 30}, TrackInterpolation::ease_in_out);
    CHECK(at(t, 6) == Approx(5));    // s = 0.5 -> 0.5
    CHECK(at(t, 16) == Approx(20));  // second segment, also its middle
    CHECK(at(t, 11) == Approx(10));
    // ease_in at s = 0.5 is 0.3154: 0 + 10 * 0.3154
    t.interpolation = TrackInterpolation::ease_in;
    CHECK(at(t, 6) == Approx(3.154).margin(1e-3));
    // A custom curve through the track.
    t.interpolation = TrackInterpolation::bezier;
    t.bezier = {0, 0, 1, 1};
    CHECK(at(t, 3) == Approx(2));
    CHECK(at(t, 18.5) == Approx(25));
}

// ---------------------------------------------------------------------------
// Extrapolation

TEST_CASE("extrapolation before and after the keys: hold, cycle, linear", "[anim]") {
    // Keys 0 at 10, 10 at 20, 0 at 30 (linear); period 20.
    Track t = scalar_track({10, 20, 30}, {0, 10, 0});
    SECTION("hold (the default) keeps the end keys") {
        CHECK(at(t, 0) == 0);
        CHECK(at(t, -100) == 0);
        CHECK(at(t, 40) == 0);
        t.values.back().x = 7;
        CHECK(at(t, 1000) == 7);
    }
    SECTION("cycle repeats the keyed span") {
        t.before = t.after = TrackExtrapolation::cycle;
        CHECK(at(t, 45) == Approx(5));   // 45 -> 25
        CHECK(at(t, 40) == Approx(10));  // 40 -> 20
        CHECK(at(t, 35) == Approx(5));   // 35 -> 15
        CHECK(at(t, 5) == Approx(5));    // 5 -> 25
        CHECK(at(t, -5) == Approx(5));   // -5 -> 15
        CHECK(at(t, 0) == Approx(10));   // 0 -> 20
    }
    SECTION("linear continues the end segments") {
        t.before = t.after = TrackExtrapolation::linear;
        CHECK(at(t, 5) == Approx(-5));  // slope +1 before 10
        CHECK(at(t, 0) == Approx(-10));
        CHECK(at(t, 35) == Approx(-5));  // slope -1 after 30
        CHECK(at(t, 50) == Approx(-20));
    }
    SECTION("before and after chosen separately from YAML") {
        auto scene = load_text(
            "objects:\n  - primitive: cube\n    translate:\n      keys: { 10: [0, 0, 0], 20: "
            "[10, 0, 0], 30: [0, 0, 0] }\n      extrapolation: { before: linear, after: cycle }\n");
        const Track& y = *scene.objects[0].translate.track;
        CHECK(y.before == TrackExtrapolation::linear);
        CHECK(y.after == TrackExtrapolation::cycle);
        CHECK(facet::evaluate_track(y, 5).x == Approx(-5));
        CHECK(facet::evaluate_track(y, 45).x == Approx(5));
    }
    SECTION("a step track holds its end values even with linear extrapolation") {
        t.interpolation = TrackInterpolation::step;
        t.before = t.after = TrackExtrapolation::linear;
        t.values.back().x = 4;
        CHECK(at(t, 0) == 0);
        CHECK(at(t, 50) == 4);
    }
}

TEST_CASE("a track with one key is that key everywhere", "[anim]") {
    Track t = scalar_track({5}, {3});
    t.before = t.after = TrackExtrapolation::linear;
    CHECK(at(t, -10) == 3);
    CHECK(at(t, 5) == 3);
    CHECK(at(t, 99) == 3);
}

// ---------------------------------------------------------------------------
// Keys in seconds, and fields' ranges

TEST_CASE("time: true keys by seconds since the first frame at output.fps", "[anim]") {
    auto intensity_at = [](const std::string& output, const std::string& track, int frame) {
        auto scene = load_text("output: " + output +
                               "\nlights:\n  - type: directional\n    direction: [0, -1, 0]\n"
                               "    intensity: " +
                               track + "\n" + kMinimalObjects);
        std::vector<facet::Bounds> bounds(1);
        return facet::evaluate_frame(scene, bounds, frame).lights.at(0).intensity;
    };
    const std::string seconds = "{ keys: { 0: 1, 2: 3 }, time: true }";
    const std::string frames24 = "{ frames: 1-49, fps: 24 }";
    CHECK(intensity_at(frames24, seconds, 1) == Approx(1));     // 0 s
    CHECK(intensity_at(frames24, seconds, 13) == Approx(1.5));  // 12/24 = 0.5 s
    CHECK(intensity_at(frames24, seconds, 25) == Approx(2));    // 1 s
    CHECK(intensity_at(frames24, seconds, 49) == Approx(3));    // 2 s
    // The first frame of the range is time 0, whatever its number; fps 10.
    const std::string frames10 = "{ frames: 10-40, fps: 10 }";
    CHECK(intensity_at(frames10, seconds, 10) == Approx(1));
    CHECK(intensity_at(frames10, seconds, 20) == Approx(2));  // 10 frames = 1 s
    CHECK(intensity_at(frames10, seconds, 15) == Approx(1.5));
    // Without time: true the same keys are frames 0 and 2.
    CHECK(intensity_at(frames24, "{ keys: { 0: 1, 2: 3 } }", 25) == Approx(3));
    CHECK(intensity_at(frames24, "{ keys: { 0: 1, 2: 3 } }", 1) == Approx(2));
    // Fractional seconds as keys.
    CHECK(intensity_at(frames24, "{ keys: { 0.25: 0, 0.75: 1 }, time: true }", 13) == Approx(0.5));
}

TEST_CASE("evaluated values stay inside the field's range", "[anim]") {
    // Uniform Catmull-Rom at s = 0.5 is (P1 + P2)/2 + (P1 + P2 - P0 - P3)/16.
    // fov keys 100, 179, 179, 100: 179 + (358 - 200)/16 = 188.875 > 179.
    // colour keys 1, 0, 0, 1: 0 + (0 - 2)/16 = -0.125 < 0.
    const std::string text = R"(output: { frames: 1-7 }
camera:
  position: { keys: { 1: [100, 0, 5], 3: [179, 0, 5], 5: [179, 0, 5], 7: [100, 0, 5] }, interpolation: smooth }
  fov: { keys: { 1: 100, 3: 179, 5: 179, 7: 100 }, interpolation: smooth }
lights:
  - type: directional
    direction: [0, -1, 0]
    intensity: { keys: { 1: 1, 2: 0.5 }, extrapolation: linear }
objects:
  - primitive: cube
    material:
      color: { keys: { 1: [1, 1, 1], 3: [0, 0, 0], 5: [0, 0, 0], 7: [1, 1, 1] }, interpolation: smooth }
)";
    auto scene = load_text(text);
    std::vector<facet::Bounds> bounds(1);
    auto state = facet::evaluate_frame(scene, bounds, 4);
    // An unranged value shows the overshoot, so the clamps below mean something.
    CHECK(state.camera.position.x == Approx(188.875));
    CHECK(state.camera.fov_degrees == Approx(179));
    REQUIRE(state.objects[0].material.color);
    CHECK(*state.objects[0].material.color == glm::vec3(0));
    for (int frame = 1; frame <= 7; ++frame) {
        auto s = facet::evaluate_frame(scene, bounds, frame);
        CHECK(s.camera.fov_degrees >= 1);
        CHECK(s.camera.fov_degrees <= 179);
        CHECK(s.objects[0].material.color->r >= 0);
        // Linear extrapolation of 1 -> 0.5 would reach -1.5 at frame 6.
        CHECK(s.lights[0].intensity >= 0);
    }
    CHECK(facet::evaluate_frame(scene, bounds, 2).lights[0].intensity == Approx(0.5));
    CHECK(facet::evaluate_frame(scene, bounds, 3).lights[0].intensity == Approx(0));
}

// ---------------------------------------------------------------------------
// Rotations

TEST_CASE("rotation keys interpolate as rotations", "[anim]") {
    SECTION("0 -> 90 about Y is 45 at the middle") {
        auto r = rotation_track({1, 3}, {{0, 0, 0}, {0, 90, 0}});
        CHECK(angle_between(rotation_at(r, 2), about_y(45)) < kTiny);
        // The rotated +X axis points at (cos 45, 0, -sin 45).
        glm::dvec3 x = rotation_at(r, 2) * glm::dvec3(1, 0, 0);
        CHECK(x.x == Approx(std::sqrt(0.5)));
        CHECK(x.z == Approx(-std::sqrt(0.5)));
    }
    SECTION("170 -> -170 takes the 20 degree arc through 180") {
        auto r = rotation_track({1, 5}, {{0, 170, 0}, {0, -170, 0}});
        CHECK(angle_between(rotation_at(r, 3), about_y(180)) < kTiny);
        CHECK(angle_between(rotation_at(r, 2), about_y(175)) < kTiny);
        CHECK(angle_between(rotation_at(r, 1), rotation_at(r, 5)) == Approx(20));
        // `angles` follows the numbers instead: through 0, the long way.
        auto a = rotation_track({1, 5}, {{0, 170, 0}, {0, -170, 0}}, TrackInterpolation::linear,
                                facet::RotationPath::angles);
        CHECK(angle_between(rotation_at(a, 3), about_y(0)) < kTiny);
    }
    SECTION("0 -> 360 with automatic makes a full turn") {
        auto r = rotation_track({1, 9}, {{0, 0, 0}, {0, 360, 0}});
        CHECK(angle_between(rotation_at(r, 5), about_y(180)) < kTiny);
        CHECK(angle_between(rotation_at(r, 3), about_y(90)) < kTiny);
        CHECK(angle_between(rotation_at(r, 7), about_y(270)) < kTiny);
    }
    SECTION("rotation: shortest makes 0 -> 360 no motion at all") {
        auto r = rotation_track({1, 9}, {{0, 0, 0}, {0, 360, 0}}, TrackInterpolation::linear,
                                facet::RotationPath::shortest);
        for (int f = 1; f <= 9; ++f) CHECK(angle_between(rotation_at(r, f), about_y(0)) < kTiny);
    }
    SECTION("rotation: angles makes 0 -> 720 two turns") {
        auto r = rotation_track({1, 9}, {{0, 0, 0}, {0, 720, 0}}, TrackInterpolation::linear,
                                facet::RotationPath::angles);
        CHECK(angle_between(rotation_at(r, 2), about_y(90)) < kTiny);
        CHECK(angle_between(rotation_at(r, 3), about_y(180)) < kTiny);
        CHECK(angle_between(rotation_at(r, 4), about_y(270)) < kTiny);
        CHECK(angle_between(rotation_at(r, 5), about_y(0)) < kTiny);
        CHECK(angle_between(rotation_at(r, 6), about_y(90)) < kTiny);
    }
    SECTION("keys 120 apart turn steadily through a full circle") {
        // Each key is flipped into the previous key's hemisphere, so 240 -> 360
        // continues forward instead of jumping back.
        auto r =
            rotation_track({0, 10, 20, 30}, {{0, 0, 0}, {0, 120, 0}, {0, 240, 0}, {0, 360, 0}});
        for (int i = 0; i <= 30; ++i)
            CHECK(angle_between(rotation_at(r, i), about_y(12.0 * i)) < kTiny);
    }
    SECTION("linear extrapolation continues turning") {
        auto r = rotation_track({1, 3}, {{0, 0, 0}, {0, 90, 0}});
        std::const_pointer_cast<Track>(r.track)->after = TrackExtrapolation::linear;
        CHECK(angle_between(rotation_at(r, 5), about_y(180)) < kTiny);
    }
    SECTION("rotation: from YAML") {
        auto scene = load_text(
            "objects:\n  - primitive: cube\n    rotate: { keys: { 1: [0, 0, 0], 9: [0, 720, 0] }, "
            "rotation: angles }\n");
        CHECK(scene.objects[0].rotate.track->rotation == facet::RotationPath::angles);
        CHECK(angle_between(rotation_at(scene.objects[0].rotate, 3), about_y(180)) < kTiny);
    }
}

TEST_CASE("a multi-key rotation track never flips between frames", "[anim]") {
    // Keys on all three axes, with neighbours more than 180 apart on some axes
    // (but under 360, so the shorter arc is used).
    const std::vector<glm::dvec3> keys = {{0, 0, 0},       {90, 45, 0},    {170, 100, -60},
                                          {-170, 200, 30}, {10, -30, 170}, {-100, 80, -170}};
    for (auto mode : {TrackInterpolation::linear, TrackInterpolation::smooth,
                      TrackInterpolation::ease_in_out}) {
        INFO("interpolation " << static_cast<int>(mode));
        auto r = rotation_track({0, 10, 20, 30, 40, 50}, keys, mode);
        // Through the keys.
        for (size_t k = 0; k < keys.size(); ++k)
            CHECK(angle_between(rotation_at(r, 10.0 * k), facet::euler_to_quat(keys[k])) < kTiny);
        // Each key-to-key arc is under 180 degrees, so 0.05-frame steps (1/200 of
        // a segment) move a few degrees at most; a flip jumps by far more.
        double largest = 0;
        for (double f = 0; f < 50; f += 0.05)
            largest = std::max(largest, angle_between(rotation_at(r, f), rotation_at(r, f + 0.05)));
        CHECK(largest < 3.0);
        CHECK(largest > 0.1);  // and it does turn
    }
}

// ---------------------------------------------------------------------------
// Track syntax errors: each names file:line:column and the key path.

TEST_CASE("malformed tracks are rejected where they are written", "[anim]") {
    struct Case {
        const char* name;
        std::string entry;   // a line of objects.0, e.g. "translate: { keys: ... }"
        std::string key;     // the key path the message must quote
        std::string needle;  // text at the reported position (searched within `entry`)
        std::string says;
    };
    const std::string tr = "objects.0.translate";
    const std::vector<Case> cases = {
        {"key not a number", "translate: { keys: { 1: [0, 0, 0], a2: [1, 1, 1] } }",
         tr + ".keys.a2", "a2", "a key must be a frame number, got 'a2'"},
        {"key not a time", "translate: { keys: { 0: [0, 0, 0], 1s: [1, 1, 1] }, time: true }",
         tr + ".keys.1s", "1s", "a time in seconds"},
        {"duplicate frames 1 and 1.0", "translate: { keys: { 1: [0, 0, 0], 1.0: [1, 1, 1] } }",
         tr + ".keys.1.0", "1.0", "two keys at the same frame"},
        {"empty keys", "translate: { keys: {} }", tr + ".keys", "{}", "at least one key"},
        {"keys not a mapping", "translate: { keys: [1, 2] }", tr + ".keys", "[1, 2]", "mapping"},
        {"unknown interpolation", "translate: { keys: { 1: [0, 0, 0] }, interpolation: smoth }",
         tr + ".interpolation", "smoth",
         "step, linear, smooth, ease_in, ease_out, ease_in_out, bezier"},
        {"misspelt track key", "translate: { keys: { 1: [0, 0, 0] }, interpolaton: step }",
         tr + ".interpolaton", "interpolaton", "did you mean 'interpolation'"},
        {"bezier handles without interpolation: bezier",
         "translate: { keys: { 1: [0, 0, 0] }, bezier: [0.1, 0, 0.9, 1] }", tr + ".bezier", "[0.1",
         "interpolation: bezier"},
        {"interpolation: bezier without handles",
         "translate: { keys: { 1: [0, 0, 0] }, interpolation: bezier }", tr + ".interpolation",
         "bezier", "bezier: [x1, y1, x2, y2]"},
        {"x1 out of [0, 1]",
         "translate: { keys: { 1: [0, 0, 0] }, interpolation: bezier, bezier: [1.5, 0, 0.5, 1] }",
         tr + ".bezier.0", "1.5", "between 0 and 1"},
        {"x2 out of [0, 1]",
         "translate: { keys: { 1: [0, 0, 0] }, interpolation: bezier, bezier: [0.5, 0, -0.1, 1] }",
         tr + ".bezier.2", "-0.1", "between 0 and 1"},
        {"bezier with three numbers",
         "translate: { keys: { 1: [0, 0, 0] }, interpolation: bezier, bezier: [0.5, 0, 1] }",
         tr + ".bezier", "[0.5, 0, 1]", "[x1, y1, x2, y2]"},
        {"key value of the wrong shape", "translate: { keys: { 1: [0, 0, 0], 5: [1, 2] } }",
         tr + ".keys.5", "[1, 2]", ""},
        {"a number where a point is needed", "translate: { keys: { 1: [0, 0, 0], 5: 7 } }",
         tr + ".keys.5", "7 }", ""},
        {"key value outside the field's range",
         "material: { specular: { keys: { 1: 0.5, 5: 2000 } } }",
         "objects.0.material.specular.keys.5", "2000", "between 0 and 1000"},
        {"a negative colour as a key",
         "material: { color: { keys: { 1: [1, 1, 1], 2: [1, -1, 0] } } }",
         "objects.0.material.color.keys.2.1", "-1, 0]", ">= 0"},
        {"unknown extrapolation", "translate: { keys: { 1: [0, 0, 0] }, extrapolation: bounce }",
         tr + ".extrapolation", "bounce", "hold, cycle, linear"},
        {"unknown extrapolation side",
         "translate: { keys: { 1: [0, 0, 0] }, extrapolation: { after: hold, during: cycle } }",
         tr + ".extrapolation.during", "during", "unknown key"},
        {"rotation path on a non-rotation",
         "translate: { keys: { 1: [0, 0, 0] }, rotation: angles }", tr + ".rotation",
         "rotation:", "unknown key"},
        {"time not a boolean", "translate: { keys: { 1: [0, 0, 0] }, time: seconds }", tr + ".time",
         "seconds", ""},
    };
    for (const Case& c : cases) {
        DYNAMIC_SECTION(c.name) {
            TempDir dir("track-error");
            const std::string text = "objects:\n  - primitive: cube\n    " + c.entry + "\n";
            const std::string path = write_text(dir.file("bad.yaml"), text);
            const std::string message = load_error(path);
            // The needle's first occurrence inside the entry, not in "primitive: cube".
            const size_t entry = text.find(c.entry);
            const size_t hit = text.find(c.needle, entry);
            REQUIRE(hit != std::string::npos);
            check_error_at(message, path, line_col(text, c.needle, hit - text.find(c.needle)),
                           c.key);
            if (!c.says.empty()) CHECK_THAT(message, Contains(c.says));
        }
    }
}

TEST_CASE("a rotation track's rotation: must be auto, shortest or angles", "[anim]") {
    TempDir dir("track-error");
    const std::string text =
        "objects:\n  - primitive: cube\n    rotate: { keys: { 1: [0, 0, 0] }, rotation: long }\n";
    const std::string path = write_text(dir.file("bad.yaml"), text);
    const std::string message = load_error(path);
    check_error_at(message, path, line_col(text, "long"), "objects.0.rotate.rotation");
    CHECK_THAT(message, Contains("auto, shortest, angles"));
}
