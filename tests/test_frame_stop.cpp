// FrameRenderer's stop query (render/frame_renderer.hpp): once it answers
// true during a frame, the tiles not yet shaded and the stages after
// shading are skipped (facet preview drops a view the user has moved on
// from); the renderer then renders the next frame as if nothing had
// happened.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>

#include "core/thread_pool.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

bool same_pixels(const HalfColorImage& a, const HalfColorImage& b) {
    if (a.width != b.width || a.height != b.height) return false;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        if (a.pixels[i].r != b.pixels[i].r || a.pixels[i].g != b.pixels[i].g ||
            a.pixels[i].b != b.pixels[i].b || a.pixels[i].a != b.pixels[i].a)
            return false;
    return true;
}

// How many pixels of `image` still hold `marker`.
size_t pixels_holding(const HalfColorImage& image, const Rgba16F& marker) {
    size_t count = 0;
    for (const Rgba16F& p : image.pixels)
        count += p.r == marker.r && p.g == marker.g && p.b == marker.b && p.a == marker.a;
    return count;
}

// A scene of many tiles: a cube on a floor that fills the frame.
std::string scene_text(const std::string& style) {
    return "output: { size: [512, 384], samples: 4 }\n"
           "style: " +
           style +
           "\n"
           "camera: { position: [0, 1.5, 4], target: [0, 0.3, 0] }\n"
           "objects:\n"
           "  - primitive: cube\n"
           "  - { primitive: plane, scale: [40, 1, 40], translate: [0, -0.5, 0] }\n";
}

}  // namespace

TEST_CASE("a stop during a frame skips the tiles after it, and the next frame renders whole",
          "[render]") {
    TempDir dir("frame-stop");
    // Shading straight to pixels; and outlines with occlusion, which shade
    // every sample first and resolve them into pixels after further stages.
    const bool per_sample = GENERATE(false, true);
    const std::string style =
        per_sample ? "{ extends: toon-outline, occlusion: { radius: 0.3 } }" : "blinn-phong";
    INFO("style " << style);
    const SceneDesc scene = load(write_text(dir.file("scene.yaml"), scene_text(style)));
    const World world = build_world(scene);
    ThreadPool pool(2);
    FrameRenderer renderer(scene, world, pool);
    FrameImages whole;
    renderer.render(1, 0, whole);

    // The buffers are reused at the same size: every pixel the frame does
    // not reach keeps this marker.
    const Rgba16F marker = to_half(glm::vec4(0.25f, 0.5f, 0.75f, 0.5f));
    FrameImages stopped = whole;
    std::fill(stopped.color.pixels.begin(), stopped.color.pixels.end(), marker);
    // The stop arrives while the third tile is about to be shaded.
    std::atomic<int> asked{0};
    renderer.render(1, 0, stopped, [&] { return ++asked > 2; });
    const size_t total = stopped.color.pixels.size();
    const size_t untouched = pixels_holding(stopped.color, marker);
    // Asked before each tile: not once per tile of the frame, but until the stop.
    CHECK(asked > 2);
    if (per_sample) {
        // Shading wrote samples; the stages that make pixels of them were skipped.
        CHECK(untouched == total);
    } else {
        // The tiles shaded before the stop, at most one per thread after it.
        CHECK(untouched < total);
        CHECK(untouched > total / 2);
    }
    CHECK_FALSE(same_pixels(stopped.color, whole.color));

    FrameImages again;
    renderer.render(1, 0, again, [] { return false; });
    CHECK(same_pixels(again.color, whole.color));
}
