// Every style preset over a shadow catcher (material shadow_catcher: true,
// the ground of `facet scene`'s turntable): the catcher draws no line of
// its own (outline, crease, wireframe, intersection) and its shadows are
// never black, since the light no shadow map blocks (ambient, environment)
// still reaches them (docs/styles.md, "Shadow catchers").
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

#include "core/half.hpp"
#include "render_check.hpp"
#include "support.hpp"

using facet::test::pixel_at;

namespace {

// A ball over a ground seen from above, the ground's far edge across the
// frame above the ball, lit straight down so the ball's shadow is the disc
// under it. Without `ground`, the same scene with nothing under the ball.
facet::FrameImages ball(const std::string& preset, bool ground) {
    facet::test::TempDir dir("catcher-presets");
    std::string text = R"(output: { size: [120, 90], background: [0.5, 0.5, 0.5] }
camera: { position: [0, 3, 4], target: [0, 0, 0], fov: 40 }
style: )" + preset + R"(
lights:
  - { type: directional, direction: [0, -1, 0], intensity: 1, shadows: true }
objects:
  - name: ball
    primitive: sphere
    translate: [0, 0.6, 0]
    material: { color: [0.8, 0.5, 0.3] }
)";
    if (ground)
        text += R"(  - name: ground
    primitive: { type: plane, size: 8 }
    material: { shadow_catcher: true }
)";
    return facet::test::render_yaml(dir.path(), text, 1, 2);
}

std::vector<std::string> presets() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(facet::test::styles_dir()))
        if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The first row (from the top) where the image without the ground shows
// anything but the background: the ball's top.
int top_of_ball(const facet::FrameImages& alone) {
    const facet::Rgba16F corner = alone.color.at(0, 0);
    for (int y = 0; y < alone.color.height; ++y)
        for (int x = 0; x < alone.color.width; ++x) {
            const facet::Rgba16F p = alone.color.at(x, y);
            if (p.r != corner.r || p.g != corner.g || p.b != corner.b) return y;
        }
    return alone.color.height;
}

}  // namespace

TEST_CASE("every preset: a shadow catcher draws no line of its own, and its shadow is not black",
          "[render][shadow_catcher][styles]") {
    const std::vector<std::string> names = presets();
    REQUIRE(names.size() >= 20);
    for (const std::string& name : names) {
        INFO("preset " << name);
        const facet::FrameImages with = ball(name, true);
        const facet::FrameImages alone = ball(name, false);
        // Above the ball only the ground's far edge could differ: nothing may.
        const int top = top_of_ball(alone);
        REQUIRE(top > 10);
        float largest = 0.0f;
        for (int y = 0; y < top - 2; ++y)
            for (int x = 0; x < with.color.width; ++x) {
                const glm::vec4 a = facet::to_float(with.color.at(x, y));
                const glm::vec4 b = facet::to_float(alone.color.at(x, y));
                for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(a[c] - b[c]));
            }
        CHECK(largest <= 2.0f / 255.0f);
        // The shadow's middle, under the ball: some light still reaches it.
        const glm::vec4 shadow = pixel_at(with, with.color, {0.0f, 0.0f, 0.2f});
        INFO("in the shadow " << shadow.r << " " << shadow.g << " " << shadow.b);
        CHECK(std::max({shadow.r, shadow.g, shadow.b}) > 0.02f);
    }
}
