// glTF animations chosen in a scene: errors for bad choices, and posing that
// reaches the rendered pixels, loops and holds as the scene says.
#include <catch2/catch.hpp>

#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

std::string tentacle_scene(const std::string& animation) {
    return "output: { size: [48, 64], frames: \"1-100\", fps: 24 }\n"
           "style: unlit\n"
           "camera: { position: [0, 0.8, 4], target: [0, 0.8, 0], fov: 40 }\n"
           "objects:\n"
           "  - name: tentacle\n"
           "    mesh: " +
           source_path("scenes/assets/tentacle.glb") + "\n    animation: " + animation + "\n";
}

ColorImage render_frame(const SceneDesc& scene, const World& world, int frame) {
    ThreadPool pool(1);
    FrameRenderer renderer(scene, world, pool);
    FrameImages images;
    renderer.render(frame, 0, images);
    return to_float_image(images.color);
}

bool same_pixels(const ColorImage& a, const ColorImage& b) {
    return a.pixels == b.pixels;
}

}  // namespace

TEST_CASE("an animation name the file does not have is an error listing its animations",
          "[anim][gltf]") {
    TempDir dir("scene-animation");
    const std::string text = tentacle_scene("walk");
    const std::string path = write_text(dir.file("s.yaml"), text);
    const SceneDesc scene = load(path);
    try {
        build_world(scene);
        FAIL("build_world accepted a missing animation");
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::invalid_input);
        const std::string message = e.what();
        CHECK_THAT(message, Contains(path + ":" + line_col(text, "walk")));
        CHECK_THAT(message, Contains("objects.0.animation"));
        CHECK_THAT(message, Contains("sway"));
    }
}

TEST_CASE("a primitive cannot play an animation", "[anim][scene]") {
    TempDir dir("scene-animation");
    const std::string text = "objects:\n  - primitive: cube\n    animation: spin\n";
    const std::string path = write_text(dir.file("s.yaml"), text);
    const std::string message = load_error(path);
    check_error_at(message, path, line_col(text, "spin"), "objects.0.animation");
    CHECK_THAT(message, Contains("glTF"));
}

TEST_CASE("a glTF animation moves the rendered mesh, loops, and holds when told",
          "[anim][gltf][render]") {
    TempDir dir("scene-animation");
    // sway is a 2-second loop: 48 frames at 24 fps.
    const SceneDesc looping = load(write_text(dir.file("loop.yaml"), tentacle_scene("sway")));
    const World world = build_world(looping);
    const ColorImage f1 = render_frame(looping, world, 1);
    const ColorImage f13 = render_frame(looping, world, 13);
    const ColorImage f49 = render_frame(looping, world, 49);
    CHECK_FALSE(same_pixels(f1, f13));  // half a swing later the tentacle has moved
    CHECK(same_pixels(f1, f49));        // one period later it is back

    // By index, not looping: after the end (frame 49 = 2 s) the pose holds.
    const SceneDesc held =
        load(write_text(dir.file("hold.yaml"), tentacle_scene("{ name: \"0\", loop: false }")));
    const World held_world = build_world(held);
    const ColorImage h49 = render_frame(held, held_world, 49);
    const ColorImage h70 = render_frame(held, held_world, 70);
    CHECK(same_pixels(h49, h70));
    CHECK_FALSE(same_pixels(h49, render_frame(held, held_world, 13)));

    // Speed 2 reaches frame 13's pose at frame 7.
    const SceneDesc fast =
        load(write_text(dir.file("fast.yaml"), tentacle_scene("{ name: sway, speed: 2 }")));
    const World fast_world = build_world(fast);
    CHECK(same_pixels(render_frame(fast, fast_world, 7), f13));
}
