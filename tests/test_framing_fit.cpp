// `frame:` fits beyond the bounding sphere: `fit: geometry` (the projected
// vertices exactly, centred), an orbit's default fit (the union of the
// views over the whole turn), and animated meshes framed over their poses.
// Each is checked by projecting the world's own vertices here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "anim/frame_state.hpp"
#include "assets/gltf_pose.hpp"
#include "gltf_anim_support.hpp"
#include "render/camera.hpp"
#include "render/framing_shapes.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using namespace facet;
using namespace facet::test;

namespace {

// How the framed vertices project: the extremes of NDC x and y.
struct Extent {
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    double fill() const { return std::max({-min_x, max_x, -min_y, max_y}); }
    bool inside(double slack = 1e-4) const { return fill() <= 1 + slack; }
};

Extent extent_at(const SceneDesc& scene, const World& world,
                 const std::vector<FramingShape>& shapes, int frame,
                 const std::vector<glm::vec3>* posed = nullptr) {
    const FrameState state =
        evaluate_frame(scene, world.object_bounds, frame, 0, FrameAssets{shapes, {}, {}});
    const float aspect = float(scene.output.width) / float(scene.output.height);
    const CameraMatrices m = make_camera(state.camera, aspect);
    Extent e;
    auto add = [&](const glm::vec3& p, const glm::mat4& model) {
        const glm::dvec4 world_point = glm::dmat4(model) * glm::dvec4(glm::dvec3(p), 1.0);
        const glm::dvec4 clip = glm::dmat4(m.view_projection) * world_point;
        REQUIRE(clip.w > 0);
        e.min_x = std::min(e.min_x, clip.x / clip.w), e.max_x = std::max(e.max_x, clip.x / clip.w);
        e.min_y = std::min(e.min_y, clip.y / clip.w), e.max_y = std::max(e.max_y, clip.y / clip.w);
    };
    if (posed) {
        for (const glm::vec3& p : *posed) add(p, state.objects[0].transform);
        return e;
    }
    for (const Draw& d : world.draws)
        for (uint32_t v = d.first_vertex; v < d.first_vertex + d.vertex_count; ++v)
            add(world.positions[v], state.objects[d.object].transform);
    return e;
}

std::string knot_scene(const std::string& camera, const std::string& frames = "1") {
    return "output: { size: [160, 90], frames: \"" + frames + "\" }\ncamera: " + camera +
           "\nobjects:\n  - mesh: " + source_path("scenes/assets/knot.glb") +
           "\n    rotate: [20, 30, 0]\n";
}

}  // namespace

TEST_CASE("fit: geometry fits the projected vertices exactly, centred", "[camera][framing]") {
    TempDir dir("framing");
    for (const char* aspect : {"[160, 90]", "[90, 160]"}) {
        INFO(aspect);
        std::string text = knot_scene(
            "{ position: [3, 1, 2], fov: 40, frame: { objects: all, margin: 0, fit: geometry } }");
        text.replace(text.find("[160, 90]"), 9, aspect);
        const SceneDesc scene = load(write_text(dir.file("fit.yaml"), text));
        const World world = build_world(scene);
        const std::vector<FramingShape> shapes = framing_shapes(scene, world);
        const Extent e = extent_at(scene, world, shapes, 1);
        CHECK(e.inside());
        // One axis touches both edges; the other is centred.
        CHECK(e.fill() == Approx(1.0).margin(1e-4));
        CHECK(e.min_x + e.max_x == Approx(0).margin(1e-4));
        CHECK(e.min_y + e.max_y == Approx(0).margin(1e-4));
        CHECK(std::max(e.max_x - e.min_x, e.max_y - e.min_y) == Approx(2.0).margin(2e-4));
    }
    // Tighter than the box's corners, which are tighter than the sphere.
    auto distance = [&](const std::string& fit) {
        const SceneDesc scene = load(write_text(
            dir.file("fit.yaml"),
            knot_scene("{ position: [3, 1, 2], fov: 40, frame: { objects: all, fit: " + fit +
                       " } }")));
        const World world = build_world(scene);
        const FrameState s = evaluate_frame(scene, world.object_bounds, 1, 0,
                                            FrameAssets{framing_shapes(scene, world), {}, {}});
        return glm::length(s.camera.position - s.camera.target);
    };
    CHECK(distance("geometry") < distance("box"));
    CHECK(distance("box") < distance("sphere"));
}

TEST_CASE("an orbit frames the union of its views: all in, and filled at the widest",
          "[camera][framing]") {
    TempDir dir("framing");
    // The default fit of an orbit; margin 0.1 leaves 1/1.1 of the half-view.
    const SceneDesc scene =
        load(write_text(dir.file("orbit.yaml"),
                        knot_scene("{ fov: 35, frame: all, orbit: { elevation: 20 } }", "1-24")));
    const World world = build_world(scene);
    const std::vector<FramingShape> shapes = framing_shapes(scene, world);
    double widest = 0, first_distance = 0;
    for (int f = 1; f <= 24; ++f) {
        INFO("frame " << f);
        const Extent e = extent_at(scene, world, shapes, f);
        CHECK(e.fill() <= 1 / 1.1 + 1e-4);
        widest = std::max(widest, e.fill());
        // No breathing: the distance stays the same all the way round.
        const FrameState s =
            evaluate_frame(scene, world.object_bounds, f, 0, FrameAssets{shapes, {}, {}});
        const double distance = glm::length(s.camera.position - s.camera.target);
        if (f == 1) first_distance = distance;
        CHECK(distance == Approx(first_distance).epsilon(1e-6));
    }
    CHECK(widest >= 1 / 1.1 - 0.01);
    // The bounding sphere, for comparison, leaves the model smaller.
    const SceneDesc sphere = load(write_text(
        dir.file("sphere.yaml"),
        knot_scene("{ fov: 35, frame: { objects: all, fit: sphere }, orbit: { elevation: 20 } }",
                   "1-24")));
    double sphere_widest = 0;
    for (int f = 1; f <= 24; ++f)
        sphere_widest = std::max(sphere_widest, extent_at(sphere, world, shapes, f).fill());
    CHECK(sphere_widest < widest - 0.05);
}

TEST_CASE("an animated mesh is framed by its poses over the scene's frames", "[camera][framing]") {
    TempDir dir("framing");
    // The arm swings 8 units along +X over one second; its rest pose alone
    // would leave it out of the frame by the end.
    Gltf g;
    const BoxAndArm nodes = box_and_arm(g);
    const int swing = add_animation(g, "Swing");
    add_channel(g, swing, nodes.arm, "translation", {0, 1}, {0, 0, 5, 8, 0, 5});
    const std::string mesh = g.write(dir.file("swing.gltf"));
    const SceneDesc scene =
        load(write_text(dir.file("swing.yaml"),
                        "output: { size: [160, 90], frames: \"1-25\", fps: 24 }\n"
                        "camera: { position: [0, 6, 12], frame: { objects: all, fit: geometry } }\n"
                        "objects:\n  - mesh: " +
                            mesh + "\n    animation: Swing\n"));
    const World world = build_world(scene);
    const std::vector<FramingShape> shapes = framing_shapes(scene, world);
    REQUIRE(shapes.size() == 1);
    // The animation loops, so frame 25 is frame 1 again; at frame 24 the
    // arm's triangle spans x = 7.67 .. 8.67.
    CHECK(shapes[0].bounds.max.x == Approx(8 * 23.0 / 24 + 1).epsilon(1e-5));
    for (int f : {1, 13, 24}) {
        INFO("frame " << f);
        const FrameState state =
            evaluate_frame(scene, world.object_bounds, f, 0, FrameAssets{shapes, {}, {}});
        std::vector<PosedPart> parts;
        pose_mesh(*world.animated_meshes[0].mesh, world.animated_meshes[0].animations,
                  animation_clock(world.animated_meshes[0], state.objects[0].animation_seconds),
                  parts);
        std::vector<glm::vec3> posed;
        for (const PosedPart& p : parts)
            posed.insert(posed.end(), p.positions.begin(), p.positions.end());
        CHECK(extent_at(scene, world, shapes, f, &posed).inside());
    }
    // The same frames with the rest pose's bounds alone lose the arm.
    const FrameState rest = evaluate_frame(scene, world.object_bounds, 24);
    std::vector<PosedPart> parts;
    pose_mesh(*world.animated_meshes[0].mesh, world.animated_meshes[0].animations,
              animation_clock(world.animated_meshes[0], rest.objects[0].animation_seconds), parts);
    std::vector<glm::vec3> posed;
    for (const PosedPart& p : parts)
        posed.insert(posed.end(), p.positions.begin(), p.positions.end());
    CHECK_FALSE(extent_at(scene, world, {}, 24, &posed).inside());
}

TEST_CASE("framing errors name the key", "[camera][framing]") {
    TempDir dir("framing");
    require_input_error(
        [&] {
            load(write_text(dir.file("bad.yaml"),
                            "camera: { frame: { objects: all, fit: tight } }\nobjects:\n"
                            "  - primitive: cube\n"));
        },
        "fit");
}
