// Keyed cloth values (seed 004 keys "the wind and the parameters"): mass,
// stiffness, friction and damping follow their keys frame by frame, the
// step is small enough for every frame's values, and a key that no step
// could make stable fails before rendering, naming the frame.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "anim/cloth_scene.hpp"
#include "cloth/cloth.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

std::string cloth_scene(const std::string& cloth_keys) {
    return "output: { size: [32, 24], frames: 1-40, fps: 24 }\n"
           "objects:\n  - name: flag\n    cloth:\n      size: [1.5, 1.0]\n      grid: [12, 8]\n"
           "      pin: left_edge\n" +
           cloth_keys + "      wind: { direction: [1, 0, 0.3], strength: 6, gust: 0.2 }\n";
}

struct Run {
    std::shared_ptr<const ClothModel> model;
    std::vector<std::vector<glm::dvec3>> positions;  // per frame 0..39
};

Run simulate(const SceneDesc& scene) {
    const ObjectDesc& obj = scene.objects[0];
    const OutputDesc& out = scene.output;
    Run run;
    run.model = build_scene_cloth(obj, out);
    const auto sim = scene_cloth_simulation(obj, out, run.model);
    for (int f = 0; f < 40; ++f) run.positions.push_back(sim->simulate_to(f).positions);
    return run;
}

double largest_difference(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, glm::length(a[i] - b[i]));
    return d;
}

}  // namespace

TEST_CASE("keyed stiffness takes effect at its key and not before", "[cloth]") {
    TempDir dir("cloth-keys");
    const Run constant = simulate(load(
        write_text(dir.file("a.yaml"), cloth_scene("      stiffness: 100\n      substeps: 40\n"))));
    const Run keyed = simulate(load(write_text(
        dir.file("b.yaml"),
        cloth_scene(
            "      stiffness: { keys: { 1: 100, 20: 100, 21: 400 } }\n      substeps: 40\n"))));
    // Scene frames 1-20 are simulation frames 0-19: the same stiffness, the
    // same step, the same bits.
    for (int f = 0; f < 20; ++f) CHECK(keyed.positions[f] == constant.positions[f]);
    // Four times stiffer from frame 21: the cloth moves differently after.
    CHECK(largest_difference(keyed.positions[39], constant.positions[39]) > 1e-4);
}

TEST_CASE("automatic substeps cover the stiffest keyed frame", "[cloth]") {
    TempDir dir("cloth-keys");
    const SceneDesc soft =
        load(write_text(dir.file("a.yaml"), cloth_scene("      stiffness: 100\n")));
    const SceneDesc stiff =
        load(write_text(dir.file("b.yaml"), cloth_scene("      stiffness: 5000\n")));
    const SceneDesc keyed = load(write_text(
        dir.file("c.yaml"), cloth_scene("      stiffness: { keys: { 1: 100, 40: 5000 } }\n")));
    const int soft_steps = build_scene_cloth(soft.objects[0], soft.output)->substeps;
    const int stiff_steps = build_scene_cloth(stiff.objects[0], stiff.output)->substeps;
    const int keyed_steps = build_scene_cloth(keyed.objects[0], keyed.output)->substeps;
    CHECK(stiff_steps > soft_steps);
    CHECK(keyed_steps == stiff_steps);
    // Every frame of the keyed run is within the stability bound at that step.
    for (int f = 0; f < 40; ++f) {
        ClothParams p = cloth_params(keyed.objects[0], keyed.output.fps, 1, f);
        CHECK(cloth_stability_number(p, keyed_steps) <= kClothStabilityLimit);
    }
    // And any frame alone is the same as in a whole run (the step does not
    // depend on which frames are simulated).
    const Run run = simulate(keyed);
    const ObjectDesc& obj = keyed.objects[0];
    const auto alone =
        scene_cloth_simulation(obj, keyed.output, build_scene_cloth(obj, keyed.output));
    CHECK(alone->simulate_to(37).positions == run.positions[37]);
}

TEST_CASE("a keyed value no step can hold names its frame and key", "[cloth]") {
    TempDir dir("cloth-keys");
    // With 20 substeps fixed (stiffness 100 needs 12), a stiffness rising
    // linearly to 1e6 at frame 30 is already unstable at frame 2.
    const SceneDesc scene = load(write_text(
        dir.file("a.yaml"),
        cloth_scene("      substeps: 20\n      stiffness: { keys: { 1: 100, 30: 1000000 } }\n")));
    try {
        build_scene_cloth(scene.objects[0], scene.output);
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::invalid_input);
        CHECK_THAT(e.what(), Catch::Contains("frame 2: "));
        CHECK_THAT(e.what(), Catch::Contains("stiffness"));
    }
    // A keyed mass too heavy for its stiffness to carry (stretch over max_stretch).
    const SceneDesc heavy = load(write_text(
        dir.file("b.yaml"), cloth_scene("      mass: { keys: { 1: 0.3, 10: 1000 } }\n")));
    CHECK_THROWS_AS(build_scene_cloth(heavy.objects[0], heavy.output), Error);
}
