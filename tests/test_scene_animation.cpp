// glTF animations chosen in a scene: errors for bad choices, and posing that
// reaches the rendered pixels, loops and holds as the scene says.
#include <catch2/catch.hpp>

#include "core/half.hpp"
#include "core/thread_pool.hpp"
#include "gltf_anim_support.hpp"
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

TEST_CASE("a scene plays all of a file's animations, or the ones it names", "[anim][scene]") {
    TempDir dir("scene-animations");
    Gltf g;
    const auto [box, arm] = box_and_arm(g);
    add_channel(g, add_animation(g, "BoxAction"), box, "translation", {0, 2}, {0, 0, 0, 4, 0, 0});
    add_channel(g, add_animation(g, "ArmAction"), arm, "scale", {0, 3}, {1, 1, 1, 3, 3, 3});
    add_channel(g, add_animation(g, "Idle"), arm, "rotation", {0, 1},
                concat({z_turn(0), z_turn(90)}));
    const std::string file = g.write(dir.file("actions.gltf"));
    auto world_for = [&](const std::string& animation) {
        const std::string scene =
            "output: { size: [32, 32], frames: \"1-48\" }\n"
            "camera: { position: [0, 0, 20], target: [0, 0, 0] }\n"
            "objects:\n  - mesh: " +
            file + "\n    animation: " + animation + "\n";
        return build_world(load(write_text(dir.file("s.yaml"), scene)));
    };
    const World all = world_for("all");
    REQUIRE(all.animated_meshes.size() == 1);
    CHECK(all.animated_meshes[0].animations == std::vector<int>{0, 1, 2});
    CHECK(all.animated_meshes[0].duration == 3.0);  // the longest
    const World two = world_for("[ArmAction, BoxAction]");
    CHECK(two.animated_meshes[0].animations == std::vector<int>{0, 1});
    const World mapped = world_for("{ name: [Idle], speed: 2 }");
    CHECK(mapped.animated_meshes[0].animations == std::vector<int>{2});
    CHECK(mapped.animated_meshes[0].duration == 1.0);
    try {
        world_for("[BoxAction, Walk]");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK_THAT(e.what(), Contains("objects.0.animation"));
        CHECK_THAT(e.what(), Contains("no animation 'Walk'"));
    }
    CHECK_THROWS_WITH(world_for("[]"), Contains("give at least one animation name"));

    // facet info names the nodes each animation drives.
    const RunResult info = run_facet("info '" + file + "'");
    CHECK_THAT(info.output, Contains("BoxAction: 2 s, 1 channel, drives Box"));
    CHECK_THAT(info.output, Contains("ArmAction: 3 s, 1 channel, drives Arm"));
    const auto described = nlohmann::json::parse(
        run_command("'" + facet::test::facet_executable() + "' info '" + file + "' --json").output);
    CHECK(described["animations"][0]["nodes"] == nlohmann::json::array({"Box"}));
    CHECK(described["animations"][2]["nodes"] == nlohmann::json::array({"Arm"}));
}

TEST_CASE("a pose that mirrors a single-sided mesh keeps its front faces", "[anim][gltf][render]") {
    // A triangle facing the camera, its X scale animated from 1 to -1: the
    // mirror reverses the winding on screen; the front must stay the front
    // (drawn, and lit from the front), not be culled as a back face.
    TempDir dir("scene-mirror");
    Gltf g;
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    add_channel(g, add_animation(g, "mirror"), 0, "scale", {0, 1}, {1, 1, 1, -1, 1, 1}, "STEP");
    const std::string file = g.write(dir.file("mirror.gltf"));
    const std::string text =
        "output: { size: [64, 64], frames: \"1-48\", fps: 24, background: [0, 0, 0, 1] }\n"
        "style: phong\n"
        "camera: { position: [0, 0.3, 3], target: [0, 0.3, 0], fov: 60 }\n"
        "lights: [ { type: directional, direction: [0, 0, -1] } ]\n"
        "objects:\n  - mesh: " +
        file + "\n    animation: { name: mirror, loop: false }\n";
    const SceneDesc scene = load(write_text(dir.file("s.yaml"), text));
    const World world = build_world(scene);
    auto lit_pixels = [&](int frame, float& brightest) {
        const ColorImage image = render_frame(scene, world, frame);
        size_t lit = 0;
        brightest = 0;
        for (const glm::vec4& p : image.pixels)
            if (p.r > 0.05f) {
                ++lit;
                brightest = std::max(brightest, p.r);
            }
        return lit;
    };
    float rest_light = 0, mirrored_light = 0;
    const size_t rest = lit_pixels(1, rest_light);
    const size_t mirrored = lit_pixels(40, mirrored_light);  // 1.6 s: scale -1
    CHECK(rest > 100);
    CHECK(mirrored == rest);  // the mirror image of the same triangle
    CHECK(mirrored_light == Approx(rest_light).epsilon(1e-3));
}
