// Camera placement (src/anim/camera_path.cpp, src/anim/frame_state.cpp):
// spline paths at constant speed, orbits, following an object, framing
// objects for any fov and aspect, and frame-subset determinism of an
// animated scene.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "anim/camera_path.hpp"
#include "anim/frame_state.hpp"
#include "job/render_job.hpp"
#include "output/manifest.hpp"
#include "render/camera.hpp"
#include "render/world.hpp"
#include "render_hashes.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using test::TempDir;
using test::write_text;

namespace {

SceneDesc load_text(const std::string& text) {
    TempDir dir("campath");
    return test::load(write_text(dir.file("cam.yaml"), text));
}

// Frame `frame` of a scene whose object bounds do not matter (unit cubes).
FrameState frame_of(const SceneDesc& scene, int frame, size_t camera = 0) {
    std::vector<Bounds> bounds(scene.objects.size(), Bounds{glm::vec3(-0.5f), glm::vec3(0.5f)});
    return evaluate_frame(scene, bounds, frame, camera);
}

bool near_point(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-4) {
    return glm::length(a - b) <= eps;
}

#define CHECK_POINT(a, b)                                                                       \
    do {                                                                                        \
        const glm::dvec3 pa{a}, pb{b};                                                          \
        INFO("got (" << pa.x << ", " << pa.y << ", " << pa.z << "), expected (" << pb.x << ", " \
                     << pb.y << ", " << pb.z << ")");                                           \
        CHECK(near_point(pa, pb));                                                              \
    } while (0)

}  // namespace

// ---------------------------------------------------------------------------
// SplinePath

TEST_CASE("a spline path passes through its points at constant speed", "[camera][anim]") {
    // Uneven spacing (a short segment next to a long one) and turns in 3D.
    const std::vector<glm::vec3> points = {
        {0, 0, 0}, {0.5f, 0, 0}, {6, 0, 1}, {6.5f, 2, 1}, {3, 4, -2}};
    for (bool closed : {false, true}) {
        INFO("closed " << closed);
        SplinePath path(points, closed);
        REQUIRE(path.length() > 0);
        CHECK_POINT(path.at_fraction(0), glm::dvec3(points.front()));
        if (!closed) CHECK_POINT(path.at_fraction(1), glm::dvec3(points.back()));
        if (closed) CHECK_POINT(path.at_fraction(1), glm::dvec3(points.front()));

        // Every control point lies on the curve: with constant speed, 4000
        // samples are length/4000 apart, so one lands within that of each point.
        const int n = 4000;
        std::vector<glm::dvec3> samples;
        for (int i = 0; i <= n; ++i) samples.push_back(path.at_fraction(double(i) / n));
        for (const glm::vec3& p : points) {
            double nearest = 1e30;
            for (const auto& s : samples)
                nearest = std::min(nearest, glm::length(s - glm::dvec3(p)));
            CHECK(nearest <= path.length() / n);
        }

        // Equal fraction steps cover equal lengths, within 1%. Each step's
        // length is the sum of 10 chords, so that a sharp bend inside a step
        // (the closing segment turns hard at the first point) does not make
        // the chord shorter than the arc.
        const int steps = 200, sub = 10;
        std::vector<double> chords;
        for (int i = 0; i < steps; ++i) {
            double arc = 0;
            for (int k = 0; k < sub; ++k)
                arc += glm::length(path.at_fraction(double(i * sub + k + 1) / (steps * sub)) -
                                   path.at_fraction(double(i * sub + k) / (steps * sub)));
            chords.push_back(arc);
        }
        double sum = 0;
        for (double c : chords) sum += c;
        const double mean = sum / steps;
        CHECK(sum == Approx(path.length()).epsilon(0.005));
        for (int i = 0; i < steps; ++i) {
            INFO("step " << i);
            CHECK(std::abs(chords[i] - mean) <= 0.01 * mean);
        }
    }
}

TEST_CASE("a closed path wraps round, an open one stops at its ends", "[camera][anim]") {
    const std::vector<glm::vec3> square = {{5, 1, 0}, {0, 1, 5}, {-5, 1, 0}, {0, 1, -5}};
    SplinePath closed(square, true);
    // By symmetry each control point is a quarter of the way round.
    for (int i = 0; i < 4; ++i) CHECK_POINT(closed.at_fraction(i * 0.25), glm::dvec3(square[i]));
    CHECK_POINT(closed.at_fraction(1.25), closed.at_fraction(0.25));
    CHECK_POINT(closed.at_fraction(-0.25), closed.at_fraction(0.75));
    CHECK_POINT(closed.at_fraction(3.6), closed.at_fraction(0.6));
    // Round, not a square: the middle of a side bulges out past the chord.
    CHECK(glm::length(glm::dvec2(closed.at_fraction(0.125).x, closed.at_fraction(0.125).z)) >
          std::sqrt(12.5) + 0.5);

    SplinePath open(square, false);
    CHECK_POINT(open.at_fraction(1.5), glm::dvec3(square.back()));
    CHECK_POINT(open.at_fraction(-0.5), glm::dvec3(square.front()));
}

// ---------------------------------------------------------------------------
// Cameras in scenes

TEST_CASE("a path camera runs from the first point to the last over the frames", "[camera]") {
    // Symmetric about z = 0, so the middle frame is at the middle point.
    auto open = load_text(R"(output: { frames: 1-5 }
camera:
  path: { points: [[0, 1, 5], [5, 1, 0], [0, 1, -5]] }
  target: { keys: { 1: [0, 0, 0], 5: [4, 0, 0] } }
)" + test::kMinimalObjects);
    CHECK_POINT(frame_of(open, 1).camera.position, glm::dvec3(0, 1, 5));
    CHECK_POINT(frame_of(open, 3).camera.position, glm::dvec3(5, 1, 0));
    CHECK_POINT(frame_of(open, 5).camera.position, glm::dvec3(0, 1, -5));
    CHECK_POINT(frame_of(open, 3).camera.target, glm::dvec3(2, 0, 0));  // keyed target point

    // A closed path loops like an orbit: frame 5 would be frame 1 again.
    auto closed = load_text(R"(output: { frames: 1-4 }
camera:
  path: { points: [[5, 1, 0], [0, 1, 5], [-5, 1, 0], [0, 1, -5]], closed: true }
)" + test::kMinimalObjects);
    CHECK_POINT(frame_of(closed, 1).camera.position, glm::dvec3(5, 1, 0));
    CHECK_POINT(frame_of(closed, 2).camera.position, glm::dvec3(0, 1, 5));
    CHECK_POINT(frame_of(closed, 4).camera.position, glm::dvec3(0, 1, -5));
    CHECK_POINT(frame_of(closed, 5).camera.position, glm::dvec3(5, 1, 0));

    // `at:` keys the fraction travelled.
    auto keyed = load_text(R"(output: { frames: 1-5 }
camera:
  path: { points: [[5, 1, 0], [0, 1, 5], [-5, 1, 0], [0, 1, -5]], closed: true,
          at: { keys: { 1: 0, 5: 0.25 } } }
)" + test::kMinimalObjects);
    CHECK_POINT(frame_of(keyed, 5).camera.position, glm::dvec3(0, 1, 5));
    const glm::dvec3 mid = frame_of(keyed, 3).camera.position;  // an eighth: equally far from both
    CHECK(glm::length(mid - glm::dvec3(5, 1, 0)) == Approx(glm::length(mid - glm::dvec3(0, 1, 5))));
    CHECK(glm::length(mid - glm::dvec3(5, 1, 0)) > 1);
}

TEST_CASE("orbit: start angle, direction, elevation, turns and keyed values", "[camera]") {
    auto position = [](const std::string& orbit, int frame, const std::string& frames = "1-4") {
        auto scene = load_text("output: { frames: " + frames + " }\ncamera: { orbit: " + orbit +
                               " }\n" + test::kMinimalObjects);
        return glm::dvec3(frame_of(scene, frame).camera.position);
    };
    const std::string flat = "{ radius: 5, elevation: 0";
    // 0 degrees is +Z; counterclockwise seen from above goes +Z -> +X -> -Z -> -X.
    CHECK_POINT(position(flat + " }", 1), glm::dvec3(0, 0, 5));
    CHECK_POINT(position(flat + " }", 2), glm::dvec3(5, 0, 0));
    CHECK_POINT(position(flat + " }", 3), glm::dvec3(0, 0, -5));
    CHECK_POINT(position(flat + " }", 4), glm::dvec3(-5, 0, 0));
    CHECK_POINT(position(flat + ", direction: clockwise }", 2), glm::dvec3(-5, 0, 0));
    CHECK_POINT(position(flat + ", direction: clockwise }", 4), glm::dvec3(5, 0, 0));
    CHECK_POINT(position(flat + ", direction: counterclockwise }", 2), glm::dvec3(5, 0, 0));
    CHECK_POINT(position(flat + ", start_angle: 90 }", 1), glm::dvec3(5, 0, 0));
    CHECK_POINT(position(flat + ", start_angle: 90, direction: clockwise }", 2),
                glm::dvec3(0, 0, 5));
    // Half a turn over 4 frames: a quarter turn every 2 frames.
    CHECK_POINT(position(flat + ", turns: 0.5 }", 3), glm::dvec3(5, 0, 0));
    // Elevation 30 around a centre: up by r sin 30, out by r cos 30.
    CHECK_POINT(position("{ radius: 4, elevation: 30, center: [1, 2, 3] }", 1),
                glm::dvec3(1, 2 + 2, 3 + 4 * std::cos(glm::radians(30.0))));
    // Keyed radius 2 -> 6 and elevation 0 -> 60 over frames 1-3: 4 and 30 at frame 2,
    // a quarter turn (of 1-4) round: +X.
    CHECK_POINT(
        position("{ radius: { keys: { 1: 2, 3: 6 } }, elevation: { keys: { 1: 0, 3: 60 } } }", 2),
        glm::dvec3(4 * std::cos(glm::radians(30.0)), 2, 0));
    // Keyed start angle and centre with no turning.
    CHECK_POINT(
        position("{ radius: 2, elevation: 0, turns: 0, start_angle: { keys: { 1: 0, 4: 90 } },"
                 " center: { keys: { 1: [0, 0, 0], 4: [3, 0, 0] } } }",
                 4),
        glm::dvec3(5, 0, 0));
    // The orbit looks at its centre.
    auto scene = load_text("output: { frames: 1-4 }\ncamera: { orbit: { center: [1, 2, 3] } }\n" +
                           test::kMinimalObjects);
    CHECK_POINT(frame_of(scene, 2).camera.target, glm::dvec3(1, 2, 3));
}

TEST_CASE("target: OBJECT follows the object's bounds centre as it moves", "[camera]") {
    auto scene = load_text(R"(output: { frames: 1-5 }
camera: { position: [0, 2, 8], target: mover }
objects:
  - primitive: cube
  - name: mover
    primitive: cube
    translate: { keys: { 1: [0, 0, 0], 5: [4, 0, 0] } }
    rotate: [0, 90, 0]
)");
    // Model-space bounds centred at (2, 1, 1): turned 90 about Y it is
    // (1, 1, -2), then moved by the keyed translate.
    std::vector<Bounds> bounds = {Bounds{glm::vec3(-1), glm::vec3(1)},
                                  Bounds{glm::vec3(1, 0, 0), glm::vec3(3, 2, 2)}};
    auto at = [&](int frame) { return evaluate_frame(scene, bounds, frame).camera; };
    CHECK_POINT(at(1).target, glm::dvec3(1, 1, -2));
    CHECK_POINT(at(3).target, glm::dvec3(3, 1, -2));
    CHECK_POINT(at(5).target, glm::dvec3(5, 1, -2));
    CHECK_POINT(at(3).position, glm::dvec3(0, 2, 8));
}

// ---------------------------------------------------------------------------
// Framing

namespace {

struct Projected {
    double x, y, depth;  // NDC x, y; view depth along the axis
};

Projected project(const CameraMatrices& m, const glm::dvec3& p) {
    const glm::dvec4 clip = glm::dmat4(m.view_projection) * glm::dvec4(p, 1.0);
    const glm::dvec4 view = glm::dmat4(m.view) * glm::dvec4(p, 1.0);
    return {clip.x / clip.w, clip.y / clip.w, -view.z};
}

std::vector<glm::dvec3> world_corners(const Bounds& b, const glm::mat4& model) {
    std::vector<glm::dvec3> out;
    for (int c = 0; c < 8; ++c) {
        glm::dvec3 p((c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y,
                     (c & 4) ? b.max.z : b.min.z);
        out.emplace_back(glm::dmat4(model) * glm::dvec4(p, 1.0));
    }
    return out;
}

// Framed objects: a stretched, turning box and a ball off to one side.
std::string framing_scene(double fov, int width, int height, const std::string& frame,
                          const std::string& extra = "") {
    return "output: { size: [" + std::to_string(width) + ", " + std::to_string(height) +
           "], frames: 1-8 }\n"
           "camera:\n  fov: " +
           std::to_string(fov) + "\n  position: [3, 2, 4]\n  frame: " + frame + "\n" + extra +
           R"(objects:
  - name: slab
    primitive: { type: box, size: [2, 0.5, 1] }
    translate: [1, 0.5, -0.5]
    scale: [1, 1.5, 1]
    rotate: { keys: { 1: [0, 0, 0], 8: [30, 270, 10] } }
  - name: ball
    primitive: { type: sphere, radius: 0.4, segments: 8, rings: 4 }
    translate: [-1.5, 0.3, 0.8]
)";
}

struct FitResult {
    double fill;  // largest |NDC| of what was fitted (sphere silhouette or corners)
    double distance;
};

// Checks every framed corner is in view and between near and far; returns
// how far the fitted shape reaches towards the view's edge.
FitResult check_frame(const SceneDesc& scene, const World& world, int frame, bool box) {
    const FrameState state = evaluate_frame(scene, world.object_bounds, frame);
    const double aspect = double(scene.output.width) / scene.output.height;
    const CameraMatrices m = make_camera(state.camera, static_cast<float>(aspect));
    std::vector<Sphere> spheres;
    double corner_fill = 0;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const glm::mat4& model = state.objects[i].transform;
        const Bounds& b = world.object_bounds[i];
        for (const glm::dvec3& c : world_corners(b, model)) {
            const Projected p = project(m, c);
            CHECK(std::abs(p.x) <= 1 + 1e-4);
            CHECK(std::abs(p.y) <= 1 + 1e-4);
            CHECK(p.depth >= state.camera.near);
            CHECK(p.depth <= state.camera.far);
            corner_fill = std::max({corner_fill, std::abs(p.x), std::abs(p.y)});
        }
        // The sphere around the object's transformed box, worked out here.
        const glm::dmat4 dm(model);
        const double stretch =
            std::max({glm::length(glm::dvec3(dm[0])), glm::length(glm::dvec3(dm[1])),
                      glm::length(glm::dvec3(dm[2]))});
        spheres.push_back(
            {glm::dvec3(dm * glm::dvec4((glm::dvec3(b.min) + glm::dvec3(b.max)) * 0.5, 1.0)),
             glm::length(glm::dvec3(b.max) - glm::dvec3(b.min)) * 0.5 * stretch});
    }
    const Sphere all = enclosing_sphere(spheres);
    for (const Sphere& s : spheres)
        CHECK(glm::length(s.center - all.center) + s.radius <= all.radius * (1 + 1e-9));
    const double distance = glm::length(glm::dvec3(state.camera.position) - all.center);
    if (box) return {corner_fill, distance};
    // The camera aims at the sphere's centre, so its silhouette is a circle of
    // angular radius asin(r / d): tan of that, in NDC, on the narrower side.
    CHECK(near_point(glm::dvec3(state.camera.target), all.center, 1e-3));
    const double tan_silhouette =
        all.radius / std::sqrt(distance * distance - all.radius * all.radius);
    const double fill = tan_silhouette * std::max(m.projection[0][0], m.projection[1][1]);
    return {fill, distance};
}

}  // namespace

TEST_CASE("framing fits the objects in the view for any fov and aspect", "[camera]") {
    struct Aspect {
        int w, h;
    };
    for (double fov : {20.0, 45.0, 90.0}) {
        for (Aspect a : {Aspect{160, 90}, Aspect{100, 100}, Aspect{90, 160}}) {
            for (const char* fit : {"sphere", "box"}) {
                for (double margin : {0.0, 0.1, 0.25}) {
                    const bool box = std::string(fit) == "box";
                    std::ostringstream frame;
                    frame << "{ objects: [slab, ball], fit: " << fit << ", margin: " << margin
                          << " }";
                    INFO("fov " << fov << ", " << a.w << "x" << a.h << ", " << frame.str());
                    SceneDesc scene = load_text(framing_scene(fov, a.w, a.h, frame.str()));
                    World world = build_world(scene);
                    std::vector<double> distances;
                    for (int f : {1, 4, 8}) {
                        INFO("frame " << f);
                        const FitResult r = check_frame(scene, world, f, box);
                        distances.push_back(r.distance);
                        // The fitted shape reaches 1/(1 + margin) of the way to the
                        // view's nearer edge: the margin is that fraction of the view.
                        const double expected = 1.0 / (1.0 + margin);
                        CHECK(r.fill <= 1 + 1e-4);
                        if (box)
                            CHECK(r.fill == Approx(expected).epsilon(0.01));
                        else
                            CHECK(r.fill >= expected - 0.005);
                    }
                    // A sphere fit keeps its distance while the slab turns.
                    if (!box) CHECK(distances[1] == Approx(distances[0]).epsilon(1e-5));
                    if (!box) CHECK(distances[2] == Approx(distances[0]).epsilon(1e-5));
                }
            }
        }
    }
}

TEST_CASE("framing with an orbit circles the objects at the fitted distance", "[camera]") {
    SceneDesc scene = load_text(framing_scene(45, 160, 90, "{ objects: all, fit: sphere }",
                                              "  orbit: { elevation: 25, start_angle: 30 }\n"));
    World world = build_world(scene);
    const FrameState first = evaluate_frame(scene, world.object_bounds, 1);
    const FrameState third = evaluate_frame(scene, world.object_bounds, 3);
    // A quarter turn apart (frames 1-8), at the same distance from the same centre.
    CHECK_POINT(first.camera.target, third.camera.target);
    const glm::dvec3 a = glm::dvec3(first.camera.position - first.camera.target);
    const glm::dvec3 b = glm::dvec3(third.camera.position - third.camera.target);
    CHECK(glm::length(a) == Approx(glm::length(b)).epsilon(1e-5));
    CHECK(glm::degrees(std::asin(a.y / glm::length(a))) == Approx(25).margin(1e-3));
    CHECK(glm::degrees(std::atan2(a.x, a.z)) == Approx(30).margin(1e-3));
    CHECK(glm::degrees(std::atan2(b.x, b.z)) == Approx(120).margin(1e-3));
    for (int f = 1; f <= 8; ++f) {
        INFO("frame " << f);
        const FitResult r = check_frame(scene, world, f, false);
        CHECK(r.fill <= 1 + 1e-4);
        CHECK(r.fill >= 1 / 1.1 - 0.005);
    }
}

TEST_CASE("framing one object ignores the others but near and far keep all in range", "[camera]") {
    SceneDesc scene = load_text(framing_scene(30, 100, 100, "{ objects: ball, margin: 0 }"));
    World world = build_world(scene);
    const FrameState state = evaluate_frame(scene, world.object_bounds, 1);
    // Aimed at the ball, close enough that the slab's corners fall out of view.
    CHECK_POINT(state.camera.target, glm::dvec3(-1.5, 0.3, 0.8));
    const CameraMatrices m = make_camera(state.camera, 1.0f);
    double largest = 0;
    for (const glm::dvec3& c : world_corners(world.object_bounds[0], state.objects[0].transform)) {
        const Projected p = project(m, c);
        largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    }
    CHECK(largest > 1);
    // The fitted planes still hold every object's corners.
    for (size_t i = 0; i < scene.objects.size(); ++i)
        for (const glm::dvec3& c :
             world_corners(world.object_bounds[i], state.objects[i].transform)) {
            const Projected p = project(m, c);
            CHECK(p.depth >= state.camera.near);
            CHECK(p.depth <= state.camera.far);
        }
    // Given planes are kept as they are.
    SceneDesc fixed = load_text(framing_scene(30, 100, 100, "ball", "  near: 0.5\n  far: 50\n"));
    const FrameState s2 = evaluate_frame(fixed, world.object_bounds, 1);
    CHECK(s2.camera.near == 0.5f);
    CHECK(s2.camera.far == 50.0f);
}

TEST_CASE("a framing camera fits the clip plane it is not given", "[camera]") {
    // A big box: framed, it sits well beyond the default far plane (100).
    const std::string objects = R"(objects:
  - name: hall
    primitive: { type: box, size: [300, 120, 200] }
)";
    for (const char* planes : {"", "  near: 1\n", "  far: 2000\n"}) {
        INFO("given: " << planes);
        SceneDesc scene = load_text(std::string("camera:\n  position: [1, 1, 2]\n  frame: all\n") +
                                    planes + objects);
        World world = build_world(scene);
        const FrameState state = evaluate_frame(scene, world.object_bounds, 1);
        const CameraMatrices m = make_camera(state.camera, 1280.0f / 720.0f);
        for (const glm::dvec3& c :
             world_corners(world.object_bounds[0], state.objects[0].transform)) {
            const Projected p = project(m, c);
            CHECK(p.depth >= state.camera.near);
            CHECK(p.depth <= state.camera.far);
        }
    }
}

// ---------------------------------------------------------------------------
// Frame-subset determinism of an animated scene

TEST_CASE("frames 4-5 alone render the same files as in a 1-6 run", "[anim][camera]") {
    TempDir full("anim-full"), part("anim-part");
    auto all =
        test::render_hashes("tests/scenes/anim_subset.yaml", 2, {1, 2, 3, 4, 5, 6}, full.path());
    auto some = test::render_hashes("tests/scenes/anim_subset.yaml", 2, {4, 5}, part.path());
    REQUIRE(all.size() == 24);  // 6 frames x (colour, depth) x (PNG, EXR)
    REQUIRE(some.size() == 8);
    for (const auto& [key, hash] : some) {
        INFO(key);
        CHECK(all.at(key) == hash);
    }
    // The frames really differ, so equal hashes mean something.
    CHECK(all.at("4/color/png") != all.at("5/color/png"));
    CHECK(all.at("4/depth/png") != all.at("5/depth/png"));
}
