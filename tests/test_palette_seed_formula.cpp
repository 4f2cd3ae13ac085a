// The palette-seed preset against seed 000's formula computed here, pixel by
// pixel: a sphere lit by one directional light, each pixel's normal found by
// intersecting its ray with the ideal sphere, c = a·k + t·warm + (1-t)·cool
// with t = (1 + n·l)/2, then the cels: the seed's c' = c·q (the preset's
// default) and the hue-keeping c·q/|c| (`cel_color: keep_hue`).
#include <catch2/catch.hpp>

#include <cmath>

#include "render_check.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

constexpr int kWidth = 160, kHeight = 120, kCels = 4;
constexpr float kFovDegrees = 40, kCameraZ = 4;
const glm::vec3 kColor{0.9f, 0.35f, 0.1f};                      // linear object colour k
const glm::vec3 kToLight = glm::normalize(glm::vec3(1, 1, 1));  // towards the light

std::string sphere_scene(const std::string& cel_color) {
    return "output: { size: [" + std::to_string(kWidth) + ", " + std::to_string(kHeight) +
           "], frames: 1, samples: 1 }\n"
           "style: { extends: palette-seed, cel_color: " +
           cel_color +
           ", hatching: false, specular: 0 }\n"
           "camera: { position: [0, 0, " +
           std::to_string(kCameraZ) + "], target: [0, 0, 0], fov: " + std::to_string(kFovDegrees) +
           " }\n"
           "lights:\n  - { type: directional, direction: [-1, -1, -1], shadows: false }\n"
           "objects:\n  - primitive: { type: sphere, radius: 1, segments: 512, rings: 256 }\n"
           "    material: { color: [0.9, 0.35, 0.1] }\n";
}

// The seed's colour before cels at the unit normal n (styles/palette-seed.yaml's values).
glm::vec3 seed_color(const glm::vec3& n) {
    const float t = (1 + glm::dot(n, kToLight)) / 2;
    const glm::vec3 cool = glm::vec3(0, 0, 0.4f) + 0.2f * kColor;
    const glm::vec3 warm = glm::vec3(0.4f, 0.4f, 0) + 0.6f * kColor;
    return 0.2f * kColor + t * warm + (1 - t) * cool;
}

struct Comparison {
    int checked = 0, matched = 0;
};

// Renders the sphere and compares every pixel whose ray meets the sphere
// away from its rim and away from a cel boundary with `expected(c, q)`.
template <typename Expected>
Comparison compare(const std::string& cel_color, Expected expected) {
    TempDir dir("palette-seed");
    const SceneDesc scene = load(write_text(dir.file("s.yaml"), sphere_scene(cel_color)));
    const ColorImage image = render_color(scene);

    const float tan_half = std::tan(glm::radians(kFovDegrees) / 2);
    const float aspect = static_cast<float>(kWidth) / kHeight;
    const glm::vec3 eye(0, 0, kCameraZ);
    Comparison result;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float sx = ((x + 0.5f) / kWidth * 2 - 1) * tan_half * aspect;
            const float sy = (1 - (y + 0.5f) / kHeight * 2) * tan_half;
            const glm::vec3 d = glm::normalize(glm::vec3(sx, sy, -1));
            // |eye + s d| = 1, nearest s.
            const float b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1;
            const float disc = b * b - c;
            if (disc <= 0) continue;
            const glm::vec3 n = eye + (-b - std::sqrt(disc)) * d;
            if (glm::dot(n, -d) < 0.35f) continue;  // the rim: tessellation and coverage
            const glm::vec3 col = seed_color(n);
            const float levels = glm::length(col) * kCels;
            if (std::abs(levels - std::floor(levels) - 0.5f) < 0.03f) continue;  // cel edge
            const float q = std::floor(levels + 0.5f) / kCels;
            const glm::vec3 want = expected(col, q);
            const glm::vec4 got = image.at(x, y);
            ++result.checked;
            result.matched += std::abs(got.x - want.x) < 0.01f &&
                              std::abs(got.y - want.y) < 0.01f && std::abs(got.z - want.z) < 0.01f;
        }
    return result;
}

}  // namespace

TEST_CASE("palette sphere: every pixel is the seed's c' = c·q", "[render][palette]") {
    const Comparison r = compare("seed", [](glm::vec3 c, float q) { return c * q; });
    INFO(r.matched << " of " << r.checked << " pixels match");
    CHECK(r.checked > 4000);
    CHECK(r.matched >= r.checked * 99 / 100);
}

TEST_CASE("palette sphere: keep_hue gives c·q/|c| at every pixel", "[render][palette]") {
    const Comparison r =
        compare("keep_hue", [](glm::vec3 c, float q) { return c * (q / glm::length(c)); });
    INFO(r.matched << " of " << r.checked << " pixels match");
    CHECK(r.checked > 4000);
    CHECK(r.matched >= r.checked * 99 / 100);
}
