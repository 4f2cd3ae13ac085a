// FrameRenderer's stop flag (render/frame_renderer.hpp): set while a frame
// renders, the rest of it is skipped (facet preview drops a view the user
// has moved on from); the renderer then renders the next frame as if
// nothing had happened.
#include <catch2/catch.hpp>

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

}  // namespace

TEST_CASE("a stopped frame is left unfinished and the next one renders whole", "[render]") {
    TempDir dir("frame-stop");
    // Outlines and occlusion: the per-sample path, with stages after shading.
    const std::string path = write_text(dir.file("scene.yaml"), R"(output:
  size: [96, 64]
  samples: 4
style: { extends: toon-outline, occlusion: { radius: 0.3 } }
camera: { position: [0, 1.5, 4], target: [0, 0.3, 0] }
objects:
  - primitive: cube
  - { primitive: plane, scale: [4, 1, 4], translate: [0, -0.5, 0] }
)");
    const SceneDesc scene = load(path);
    const World world = build_world(scene);
    ThreadPool pool(2);
    FrameRenderer renderer(scene, world, pool);
    FrameImages whole, stopped_images, again;
    renderer.render(1, 0, whole);

    std::atomic<bool> stop{true};
    renderer.render(1, 0, stopped_images, &stop);
    CHECK_FALSE(same_pixels(stopped_images.color, whole.color));

    std::atomic<bool> keep_going{false};
    renderer.render(1, 0, again, &keep_going);
    CHECK(same_pixels(again.color, whole.color));
}
