// A scene without `lights:` gets one key light that follows the camera
// (seed 001 starts with one light); `lights: []` means no light at all.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "anim/frame_state.hpp"
#include "render_check.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

const std::string kSphere =
    "output: { size: [64, 48], frames: 1-4, samples: 1 }\n"
    "style: phong\n"
    "camera: { orbit: { center: [0, 0, 0], radius: 4, elevation: 0 } }\n"
    "objects:\n  - primitive: { type: sphere, radius: 1 }\n"
    "    material: { color: [0.8, 0.8, 0.8], ambient: 0.1 }\n";

float mean_red(const SceneDesc& scene) {
    const ColorImage c = render_color(scene);
    // The sphere's middle third, where only the sphere is.
    double sum = 0;
    int n = 0;
    for (int y = 18; y < 30; ++y)
        for (int x = 26; x < 38; ++x, ++n) sum += c.at(x, y).x;
    return static_cast<float>(sum / n);
}

}  // namespace

TEST_CASE("the default key light comes from above and left of the camera, at every frame",
          "[scene][lights]") {
    TempDir dir("default-light");
    const SceneDesc scene = load(write_text(dir.file("s.yaml"), kSphere));
    REQUIRE(scene.lights.size() == 1);
    const std::vector<Bounds> bounds(scene.objects.size());
    for (int frame : {1, 2, 3, 4}) {
        const FrameState state = evaluate_frame(scene, bounds, frame);
        const glm::vec3 forward = glm::normalize(state.camera.target - state.camera.position);
        const glm::vec3 right = glm::normalize(glm::cross(forward, state.camera.up));
        const glm::vec3 up = glm::cross(right, forward);
        const glm::vec3 travel = state.lights[0].direction;
        INFO("frame " << frame);
        CHECK(glm::length(travel) == Approx(1.0f));
        CHECK(glm::dot(travel, forward) > 0.6f);  // away from the camera, into the scene
        CHECK(glm::dot(travel, right) > 0.2f);    // coming from the camera's left
        CHECK(glm::dot(travel, up) < -0.3f);      // and from above
    }
}

TEST_CASE("lights: [] renders without light, no lights key lights the scene", "[scene][lights]") {
    TempDir dir("default-light");
    const float lit = mean_red(load(write_text(dir.file("lit.yaml"), kSphere)));
    const float dark = mean_red(load(write_text(dir.file("dark.yaml"), kSphere + "lights: []\n")));
    // Ambient alone: k_a times the colour; the key light adds k_d n·l on top.
    CHECK(dark < 0.1f);
    CHECK(lit > 0.3f);
}
