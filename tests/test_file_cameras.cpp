// Cameras from glTF files (`camera: { from: FILE, name: NAME }`): placed by
// their node's world transform, animated by the file's animations that move
// that node or its parents, with the file's field of view and planes.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "anim/frame_state.hpp"
#include "gltf_anim_support.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene_support.hpp"

using namespace facet;
using namespace facet::test;
using json = nlohmann::json;

namespace {

constexpr double kYfov = 0.8;  // radians

// A unit quad at the origin facing +Z, a camera "Dolly" five units in front
// of it that moves 2 along +X over one second ("DollyMove"), and a still
// camera "Side" under a parent turned 90 degrees about +Y.
std::string camera_file(const TempDir& dir) {
    Gltf g;
    const int quad = g.mesh(
        {{"attributes",
          {{"POSITION",
            g.floats({-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0}, "VEC3")}}},
         {"indices", g.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, 5123)}});
    g.doc["cameras"] =
        json::array({{{"name", "Dolly"},
                      {"type", "perspective"},
                      {"perspective", {{"yfov", kYfov}, {"znear", 0.5}, {"zfar", 50}}}},
                     {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}});
    const int shown = g.node({{"name", "Quad"}, {"mesh", quad}});
    const int dolly = g.node({{"name", "DollyNode"}, {"camera", 0}, {"translation", {0, 0, 5}}});
    const int side = g.node({{"name", "Side"}, {"camera", 1}, {"translation", {0, 0, 4}}});
    // Parent turned +90 degrees about +Y: the child's +Z offset becomes +X.
    const double h = std::sqrt(0.5);
    const int turn = g.node({{"name", "Turn"}, {"rotation", {0, h, 0, h}}, {"children", {side}}});
    g.scene({shown, dolly, turn});
    const int move = add_animation(g, "DollyMove");
    add_channel(g, move, dolly, "translation", {0, 1}, {0, 0, 5, 2, 0, 5});
    return g.write(dir.file("cameras.gltf"));
}

SceneDesc scene_with(const TempDir& dir, const std::string& file, const std::string& camera) {
    return load(write_text(dir.file("scene.yaml"),
                           "output: { size: [160, 90], frames: \"1-25\", fps: 24 }\n"
                           "camera: " +
                               camera + "\nobjects:\n  - mesh: " + file + "\n"));
}

}  // namespace

TEST_CASE("a glTF camera is placed, aimed and animated by its file", "[camera][gltf]") {
    TempDir dir("file-camera");
    const std::string file = camera_file(dir);
    const SceneDesc scene = scene_with(dir, file, "{ from: cameras.gltf, name: Dolly }");
    CHECK(scene.cameras[0].name == "Dolly");
    const World world = build_world(scene);
    REQUIRE(world.file_cameras.size() == 1);
    REQUIRE(world.file_cameras[0].rig);
    CHECK(world.file_cameras[0].animations == std::vector<int>{0});
    const FrameAssets assets{{}, world.file_cameras, {}};
    const FrameState first = evaluate_frame(scene, world.object_bounds, 1, 0, assets);
    CHECK(first.camera.position.x == Approx(0).margin(1e-6));
    CHECK(first.camera.position.z == Approx(5));
    CHECK(first.camera.target.z == Approx(4));
    CHECK(first.camera.fov_degrees == Approx(kYfov * 180 / M_PI));
    CHECK(first.camera.near == Approx(0.5));
    CHECK(first.camera.far == Approx(50));
    // Frame 13 is half a second in: half way along the dolly.
    const FrameState middle = evaluate_frame(scene, world.object_bounds, 13, 0, assets);
    CHECK(middle.camera.position.x == Approx(1.0).epsilon(1e-6));
    CHECK(middle.camera.target.x == Approx(1.0).epsilon(1e-6));
    // Past the end it holds.
    const FrameState last = evaluate_frame(scene, world.object_bounds, 25, 0, assets);
    CHECK(last.camera.position.x == Approx(2.0).epsilon(1e-6));

    // Rendered: the quad is in the middle at frame 1, and to the left of it
    // by 1 / (5 tan(yfov/2)) of the half-width times 90/160 at frame 13.
    ThreadPool pool(1);
    FrameRenderer renderer(scene, world, pool);
    auto centre_x = [&](int frame) {
        FrameImages images;
        renderer.render(frame, 0, images);
        double sum = 0;
        size_t count = 0;
        for (int y = 0; y < images.depth.height; ++y)
            for (int x = 0; x < images.depth.width; ++x)
                if (std::isfinite(images.depth.at(x, y))) sum += x + 0.5, ++count;
        REQUIRE(count > 50);
        return sum / double(count);
    };
    CHECK(centre_x(1) == Approx(80).margin(0.5));
    const double ndc = 1.0 / (5 * std::tan(kYfov / 2) * (160.0 / 90.0));
    CHECK(centre_x(13) == Approx(80 - ndc * 80).margin(0.5));
}

TEST_CASE("a glTF camera under a turned parent, and the file's first camera", "[camera][gltf]") {
    TempDir dir("file-camera");
    const std::string file = camera_file(dir);
    // Unnamed in the file: named after its node.
    const SceneDesc side = scene_with(dir, file, "{ from: cameras.gltf, name: Side }");
    const World world = build_world(side);
    const FrameState s =
        evaluate_frame(side, world.object_bounds, 1, 0, FrameAssets{{}, world.file_cameras, {}});
    CHECK(s.camera.position.x == Approx(4).epsilon(1e-6));
    CHECK(s.camera.position.z == Approx(0).margin(1e-6));
    CHECK(s.camera.target.x == Approx(3).epsilon(1e-6));  // looking along -X, at the quad
    CHECK(s.camera.far == Approx(0.1 * 1e4));             // no zfar: infinite
    CHECK(world.file_cameras[0].animations.empty());
    // Without a name: the first camera of the file.
    const SceneDesc first = scene_with(dir, file, "{ from: cameras.gltf }");
    CHECK(build_world(first).file_cameras[0].camera.name == "Dolly");
}

TEST_CASE("glTF camera errors name the key and the file", "[camera][gltf][errors]") {
    TempDir dir("file-camera");
    const std::string file = camera_file(dir);
    require_input_error(
        [&] { build_world(scene_with(dir, file, "{ from: cameras.gltf, name: Crane }")); },
        "no camera named 'Crane' (it has 'Dolly', 'Side')");
    require_input_error([&] { scene_with(dir, file, "{ from: cameras.gltf, fov: 30 }"); },
                        "takes its fov from the file");
    write_text(dir.file("model.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    require_input_error([&] { scene_with(dir, file, "{ from: model.obj }"); }, "glTF files");
    Gltf none;
    none.one_node_scene({{"attributes", {{"POSITION", none.floats(kTriangle, "VEC3")}}}});
    const std::string plain = none.write(dir.file("plain.gltf"));
    require_input_error([&] { build_world(scene_with(dir, file, "{ from: plain.gltf }")); },
                        "plain.gltf has no cameras");
    Gltf ortho;
    ortho.one_node_scene({{"attributes", {{"POSITION", ortho.floats(kTriangle, "VEC3")}}}},
                         {{"camera", 0}});
    ortho.doc["cameras"] =
        json::array({{{"type", "orthographic"},
                      {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}});
    ortho.write(dir.file("ortho.gltf"));
    require_input_error([&] { build_world(scene_with(dir, file, "{ from: ortho.gltf }")); },
                        "perspective cameras only");
}

TEST_CASE("Khronos' Cameras sample: the perspective camera renders its square",
          "[camera][gltf][real]") {
    const std::string file = "/usr/share/assimp/models/glTF2/cameras/Cameras.gltf";
    if (!std::filesystem::exists(file))
        FACET_SKIP(file + " is missing (scripts/setup.sh --tests installs assimp-testmodels)");
    TempDir dir("file-camera");
    const std::string text =
        "output: { size: [160, 120], frames: \"1\" }\n"
        "camera: { from: " +
        file +
        ", name: node1 }\n"
        "assets: { allow_paths_outside: true }\n"
        "objects:\n  - mesh: " +
        file + "\n    material: { double_sided: true }\n";
    const SceneDesc scene = load(write_text(dir.file("cameras.yaml"), text));
    const World world = build_world(scene);
    const FrameState s =
        evaluate_frame(scene, world.object_bounds, 1, 0, FrameAssets{{}, world.file_cameras, {}});
    // Node 1: translation [0.5, 0.5, 3], yfov 0.7 rad, planes 0.01 and 100.
    CHECK(s.camera.position == glm::vec3(0.5f, 0.5f, 3.0f));
    CHECK(s.camera.fov_degrees == Approx(0.7 * 180 / M_PI));
    // The unit square (tilted back 45 degrees) is centred across the image.
    ThreadPool pool(1);
    FrameRenderer renderer(scene, world, pool);
    FrameImages images;
    renderer.render(1, 0, images);
    int left = 160, right = -1;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x)
            if (std::isfinite(images.depth.at(x, y)))
                left = std::min(left, x), right = std::max(right, x);
    REQUIRE(right > left);
    CHECK(left + right == Approx(159).margin(2));
    // The orthographic camera is listed, and refused when chosen.
    CHECK(load_gltf(file).cameras.size() == 2);
    require_input_error(
        [&] {
            build_world(load(
                write_text(dir.file("ortho.yaml"), "camera: { from: " + file +
                                                       ", name: node2 }\n"
                                                       "assets: { allow_paths_outside: true }\n"
                                                       "objects:\n  - mesh: " +
                                                       file + "\n")));
        },
        "orthographic");
}
