// glTF node animation (src/assets/gltf_pose.cpp): keyframe sampling with
// LINEAR, STEP and CUBICSPLINE samplers, rotations, holding before and after
// the keys, parts nothing moves, and choosing an animation. Files are built
// here, with answers computed by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/gltf_pose.hpp"
#include "gltf_anim_support.hpp"

using namespace facet::test;
using facet::Mesh;
using nlohmann::json;

namespace {

// The index of the vertex of `part` at `position` (the test meshes have no
// duplicate positions).
size_t vertex_at(const facet::MeshPart& part, glm::vec3 position) {
    for (size_t i = 0; i < part.positions.size(); ++i)
        if (glm::length(part.positions[i] - position) < 1e-6f) return i;
    FAIL("no vertex at (" << position.x << ", " << position.y << ", " << position.z << ")");
    return 0;
}

// The triangle on node 0, animated by one channel; the file is loaded back.
Mesh triangle_with_channel(const TempDir& dir, const std::string& file, const std::string& path,
                           const std::vector<float>& times, const std::vector<float>& values,
                           const std::string& interpolation, json node_extra = json::object()) {
    Gltf g;
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}},
                     std::move(node_extra));
    add_channel(g, add_animation(g, "move"), 0, path, times, values, interpolation);
    return facet::load_gltf(g.write(dir.file(file)));
}

// The angle in degrees of the posed vertex that rests at (1, 0, 0), about +Z.
double angle_of_x_vertex(const Mesh& mesh, double seconds) {
    auto parts = posed(mesh, 0, seconds);
    glm::vec3 p = parts[0].positions[vertex_at(mesh.parts[0], {1, 0, 0})];
    CHECK(p.z == Approx(0).margin(1e-6));
    return std::atan2(p.y, p.x) * 180.0 / M_PI;
}

}  // namespace

TEST_CASE("glTF LINEAR translation interpolates and holds before and after", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    Mesh mesh = triangle_with_channel(dir, "slide.gltf", "translation", {1, 3}, {0, 0, 0, 4, 0, 0},
                                      "LINEAR");
    REQUIRE(facet::animation_count(mesh) == 1);
    CHECK(facet::animation_duration(mesh, 0) == 3.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // (time, expected x offset): before the first key and past the end the
    // pose holds; NaN has no place on the timeline and holds the start.
    for (auto [t, dx] : std::vector<std::pair<double, float>>{
             {-1, 0}, {0, 0}, {1, 0}, {2, 2}, {2.5, 3}, {3, 4}, {10, 4}, {nan, 0}}) {
        INFO("t = " << t);
        auto parts = posed(mesh, 0, t);
        for (size_t v = 0; v < mesh.parts[0].positions.size(); ++v) {
            require_vec3(parts[0].positions[v], mesh.parts[0].positions[v] + glm::vec3(dx, 0, 0));
            require_vec3(parts[0].normals[v], {0, 0, 1});
        }
        CHECK_FALSE(parts[0].winding_flipped);
    }
}

TEST_CASE("glTF STEP holds each key until the next", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    Mesh mesh = triangle_with_channel(dir, "step.gltf", "translation", {0, 1, 2},
                                      {0, 0, 0, 1, 0, 0, 5, 0, 0}, "STEP");
    for (auto [t, dx] : std::vector<std::pair<double, float>>{
             {0, 0}, {0.99, 0}, {1, 1}, {1.5, 1}, {1.999, 1}, {2, 5}, {3, 5}}) {
        INFO("t = " << t);
        auto parts = posed(mesh, 0, t);
        require_vec3(parts[0].positions[vertex_at(mesh.parts[0], {0, 1, 0})], {dx, 1, 0});
    }
}

TEST_CASE("glTF CUBICSPLINE translation is the Hermite spline of its tangents", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    // Keys at t = 1 and 3 (interval 2): x goes 1 -> 3 with out-tangent 0.5
    // and in-tangent -1 (per second). The first in-tangent and the last
    // out-tangent play no part, so they are absurd here.
    const std::vector<float> values = concat({{9, 9, 9},
                                              {1, 0, 0},
                                              {0.5f, 0, 0},  // key 0
                                              {-1, 0, 0},
                                              {3, 0, 0},
                                              {7, 7, 7}});  // key 1
    Mesh mesh =
        triangle_with_channel(dir, "cubic.gltf", "translation", {1, 3}, values, "CUBICSPLINE");
    // u = 0.25: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = -0.046875;
    // x = 0.84375·1 + 0.140625·2·0.5 + 0.15625·3 + (-0.046875)·2·(-1) = 1.546875.
    // u = 0.5:  x = 0.5·1 + 0.125·2·0.5 + 0.5·3 + (-0.125)·2·(-1) = 2.375.
    for (auto [t, x] : std::vector<std::pair<double, float>>{
             {0.5, 1}, {1, 1}, {1.5, 1.546875f}, {2, 2.375f}, {3, 3}, {4, 3}}) {
        INFO("t = " << t);
        auto parts = posed(mesh, 0, t);
        require_vec3(parts[0].positions[vertex_at(mesh.parts[0], {0, 0, 0})], {x, 0, 0});
    }
}

TEST_CASE("glTF LINEAR rotation is a slerp along the shorter arc", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    SECTION("0 to 90 degrees") {
        Mesh mesh = triangle_with_channel(dir, "turn.gltf", "rotation", {0, 1},
                                          concat({z_turn(0), z_turn(90)}), "LINEAR");
        CHECK(angle_of_x_vertex(mesh, 0.5) == Approx(45).margin(1e-4));
        // A straight line between the quaternions (nlerp) would give 21.6 here.
        CHECK(angle_of_x_vertex(mesh, 0.25) == Approx(22.5).margin(1e-4));
        CHECK(angle_of_x_vertex(mesh, 1) == Approx(90).margin(1e-4));
    }
    SECTION("the second key given as -q still turns the short way") {
        std::vector<float> minus_q = z_turn(90);
        for (float& c : minus_q) c = -c;
        Mesh mesh = triangle_with_channel(dir, "turn_neg.gltf", "rotation", {0, 1},
                                          concat({z_turn(0), minus_q}), "LINEAR");
        // The long way would pass through -135 degrees.
        CHECK(angle_of_x_vertex(mesh, 0.5) == Approx(45).margin(1e-4));
        CHECK(angle_of_x_vertex(mesh, 0.75) == Approx(67.5).margin(1e-4));
    }
    SECTION("keys stored as normalised shorts") {
        Gltf g;
        g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
        // 23170/32767 = 0.70709..., close to but not exactly sin 45°.
        int out =
            g.accessor(g.view(bytes_of(std::vector<int16_t>{0, 0, 0, 32767, 0, 0, 23170, 23170})),
                       kShort, 2, "VEC4", 0, true);
        add_animation(g, "turn");
        g.doc["animations"][0]["samplers"].push_back(
            {{"input", g.floats({0, 1}, "SCALAR")}, {"output", out}});
        g.doc["animations"][0]["channels"].push_back(
            {{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}});
        Mesh mesh = facet::load_gltf(g.write(dir.file("short.gltf")));
        CHECK(angle_of_x_vertex(mesh, 1) == Approx(90).margin(1e-3));
        CHECK(angle_of_x_vertex(mesh, 0.5) == Approx(45).margin(1e-3));
    }
}

TEST_CASE("glTF CUBICSPLINE rotation is normalised", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    // Zero tangents: halfway the spline is the mean of the two quaternions,
    // which is shorter than 1 (cos 22.5°) and would shrink the mesh to 85%.
    const std::vector<float> zero = {0, 0, 0, 0};
    Mesh mesh = triangle_with_channel(dir, "cubic_turn.gltf", "rotation", {0, 2},
                                      concat({zero, z_turn(0), zero, zero, z_turn(90), zero}),
                                      "CUBICSPLINE");
    auto parts = posed(mesh, 0, 1);
    glm::vec3 p = parts[0].positions[vertex_at(mesh.parts[0], {1, 0, 0})];
    CHECK(glm::length(p) == Approx(1).margin(1e-6));
    CHECK(angle_of_x_vertex(mesh, 1) == Approx(45).margin(1e-4));
}

TEST_CASE("glTF scale animation transforms normals by the inverse transpose", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    // A tilted triangle, normal (0, -1, 1)/√2. Scaling y by 2 tilts the
    // surface to normal (0, -1, 2)/√5; scaling the normal itself would give
    // (0, -2, 1)/√5.
    Gltf g;
    const float s = 1 / std::sqrt(2.0f);
    g.one_node_scene({{"attributes",
                       {{"POSITION", g.floats({0, 0, 0, 1, 0, 0, 0, 1, 1}, "VEC3")},
                        {"NORMAL", g.floats({0, -s, s, 0, -s, s, 0, -s, s}, "VEC3")}}}});
    add_channel(g, add_animation(g, "stretch"), 0, "scale", {0, 1}, {1, 1, 1, 1, 2, 1});
    Mesh mesh = facet::load_gltf(g.write(dir.file("stretch.gltf")));
    auto parts = posed(mesh, 0, 1);
    const float r5 = std::sqrt(5.0f);
    for (const auto& n : parts[0].normals) require_vec3(n, {0, -1 / r5, 2 / r5});
    require_vec3(parts[0].positions[vertex_at(mesh.parts[0], {0, 1, 1})], {0, 2, 1});
}

TEST_CASE("glTF face normals are recomputed for the posed triangles", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    // No NORMAL attribute: flat normals from the faces. A quarter turn about
    // +X takes the triangle's normal from +Z to -Y.
    const float s = std::sqrt(0.5f);
    Mesh mesh = triangle_with_channel(dir, "flat.gltf", "rotation", {0, 1},
                                      {0, 0, 0, 1, s, 0, 0, s}, "LINEAR");
    for (const auto& n : mesh.parts[0].normals) require_vec3(n, {0, 0, 1});
    auto parts = posed(mesh, 0, 1);
    for (const auto& n : parts[0].normals) require_vec3(n, {0, -1, 0});
}

TEST_CASE("glTF parts that nothing moves are bit-identical to the baked rest", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    // Node 0 shows the triangle under an awkward static transform; node 1 is
    // an animated parent of node 2, which shows the triangle moved up by 5.
    Gltf g;
    const int mesh_index = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    g.node({{"mesh", mesh_index},
            {"translation", {0.1, -3.7, 2.2}},
            {"rotation", {0.3, -0.1, 0.2, 0.927}},
            {"scale", {1.3, 0.7, 2.9}}});
    g.node({{"children", {2}}});
    g.node({{"mesh", mesh_index}, {"translation", {0, 5, 0}}});
    g.scene({0, 1});
    add_channel(g, add_animation(g, "lift"), 1, "translation", {0, 1}, {0, 0, 0, 0, 0, 2});
    Mesh mesh = facet::load_gltf(g.write(dir.file("static.gltf")));
    REQUIRE(mesh.parts.size() == 2);
    REQUIRE(mesh.rig->parts[0].node == 0);
    REQUIRE(mesh.rig->parts[1].node == 2);
    for (int animation : {-1, 0})
        for (double t : {0.0, 0.3, 1.0}) {
            INFO("animation " << animation << " t = " << t);
            auto parts = posed(mesh, animation, t);
            CHECK(parts[0].positions == mesh.parts[0].positions);
            CHECK(parts[0].normals == mesh.parts[0].normals);
            const float dz = animation == 0 ? static_cast<float>(2 * t) : 0.0f;
            for (size_t v = 0; v < mesh.parts[1].positions.size(); ++v)
                require_vec3(parts[1].positions[v],
                             mesh.parts[1].positions[v] + glm::vec3(0, 0, dz));
        }
}

TEST_CASE("glTF a mirroring scale flips the posed winding", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    SECTION("scale animated from 1 to -1") {
        Mesh mesh =
            triangle_with_channel(dir, "mirror.gltf", "scale", {0, 1}, {1, 1, 1, -1, 1, 1}, "STEP");
        CHECK_FALSE(posed(mesh, 0, 0.5)[0].winding_flipped);
        auto parts = posed(mesh, 0, 1.5);
        CHECK(parts[0].winding_flipped);
        require_vec3(parts[0].positions[vertex_at(mesh.parts[0], {1, 0, 0})], {-1, 0, 0});
        for (const auto& n : parts[0].normals) require_vec3(n, {0, 0, 1});
    }
    SECTION("with normals from the file") {
        Gltf g;
        g.one_node_scene({{"attributes",
                           {{"POSITION", g.floats(kTriangle, "VEC3")},
                            {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")}}}});
        add_channel(g, add_animation(g, "mirror"), 0, "scale", {0, 1}, {1, 1, 1, -1, 1, 1}, "STEP");
        Mesh mesh = facet::load_gltf(g.write(dir.file("mirror_normals.gltf")));
        auto parts = posed(mesh, 0, 1.5);
        CHECK(parts[0].winding_flipped);
        // The inverse transpose of diag(-1, 1, 1) keeps +Z.
        for (const auto& n : parts[0].normals) require_vec3(n, {0, 0, 1});
    }
    SECTION("mirrored at rest, animated to 1") {
        Mesh mesh = triangle_with_channel(dir, "unmirror.gltf", "scale", {0, 1},
                                          {-1, 1, 1, 1, 1, 1}, "STEP", {{"scale", {-1, 1, 1}}});
        CHECK_FALSE(posed(mesh, 0, 0.5)[0].winding_flipped);
        CHECK(posed(mesh, 0, 1.5)[0].winding_flipped);
    }
}

TEST_CASE("glTF animations are found by name or index", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    Gltf g;
    g.one_node_scene({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    add_channel(g, add_animation(g, "1"), 0, "translation", {0, 2}, {0, 0, 0, 1, 0, 0});
    add_channel(g, add_animation(g, "run"), 0, "translation", {0.5, 0.75}, {0, 0, 0, 1, 0, 0});
    add_channel(g, add_animation(g, ""), 0, "scale", {0, 4}, {1, 1, 1, 2, 2, 2});
    const std::string path = g.write(dir.file("three.gltf"));
    Mesh mesh = facet::load_gltf(path);
    REQUIRE(facet::animation_count(mesh) == 3);
    CHECK(mesh.rig->animations[2].name == "animation2");
    CHECK(facet::animation_duration(mesh, 0) == 2.0);
    CHECK(facet::animation_duration(mesh, 1) == 0.75);
    CHECK(facet::animation_duration(mesh, 2) == 4.0);
    CHECK(facet::find_animation(mesh, "run") == 1);
    CHECK(facet::find_animation(mesh, "animation2") == 2);
    CHECK(facet::find_animation(mesh, "1") == 0);  // a name before an index
    CHECK(facet::find_animation(mesh, "2") == 2);
    CHECK(facet::find_animation(mesh, "0") == 0);
    for (const std::string missing : {"3", "walk", "", "-1", "1.0"}) {
        INFO("'" << missing << "'");
        require_input_error([&] { facet::find_animation(mesh, missing); }, "three.gltf");
        require_input_error([&] { facet::find_animation(mesh, missing); }, "'run'");
    }
    REQUIRE_THROWS_AS(facet::animation_duration(mesh, 3), facet::Error);
    std::vector<facet::PosedPart> out;
    REQUIRE_THROWS_AS(facet::pose_mesh(mesh, 3, 0, out), facet::Error);
}

TEST_CASE("glTF files without animation pose as their baked parts", "[gltf][anim]") {
    TempDir dir("gltf-anim");
    Mesh mesh = facet::load_gltf(single_mesh_file(
        dir.file("still.gltf"), kTriangle, {{"translation", {1, 2, 3}}, {"scale", {2, 2, 2}}}));
    CHECK(mesh.rig == nullptr);
    CHECK(facet::animation_count(mesh) == 0);
    require_input_error([&] { facet::find_animation(mesh, "0"); }, "no animations");
    auto parts = posed(mesh, -1, 0);
    CHECK(parts[0].positions == mesh.parts[0].positions);
    CHECK(parts[0].normals == mesh.parts[0].normals);
}

namespace {

// Two triangles on nodes "Box" and "Arm", and an animation for each, as
// Blender writes one action per object; the second file also has an
// animation that drives Box as well.
std::string two_actions_file(const TempDir& dir, bool clash) {
    Gltf g;
    const auto [box, arm] = box_and_arm(g);
    add_channel(g, add_animation(g, "BoxAction"), box, "translation", {0, 2}, {0, 0, 0, 4, 0, 0});
    add_channel(g, add_animation(g, "ArmAction"), arm, "scale", {0, 1}, {1, 1, 1, 3, 3, 3});
    if (clash)
        add_channel(g, add_animation(g, "BoxLift"), box, "translation", {0, 2}, {0, 0, 0, 0, 8, 0});
    return g.write(dir.file(clash ? "clash.gltf" : "actions.gltf"));
}

}  // namespace

TEST_CASE("glTF animations play together, each on the nodes it drives", "[gltf][anim]") {
    TempDir dir("gltf-anims");
    const Mesh mesh = facet::load_gltf(two_actions_file(dir, false));
    REQUIRE(facet::animation_count(mesh) == 2);
    CHECK(facet::find_animations(mesh, {"all"}) == std::vector<int>{0, 1});
    CHECK(facet::find_animations(mesh, {"ArmAction", "BoxAction", "0"}) ==
          std::vector<int>{0, 1});  // in the file's order, each once
    CHECK(facet::animations_duration(mesh, {0, 1}) == 2.0);
    CHECK(facet::animations_duration(mesh, {1}) == 1.0);
    require_input_error([&] { facet::find_animations(mesh, {"BoxAction", "Walk"}); }, "'Walk'");

    // At 1 s: Box has moved 2 along x; Arm's scale reached 3 and holds.
    auto both = posed_with(mesh, {0, 1}, 1.0);
    const size_t x_vertex = vertex_at(mesh.parts[0], {1, 0, 0});
    CHECK(both[0].positions[x_vertex].x == Approx(3.0f));
    CHECK(both[1].positions[vertex_at(mesh.parts[1], {1, 0, 5})].x == Approx(3.0f));
    auto later = posed_with(mesh, {0, 1}, 1.75);
    CHECK(later[1].positions == both[1].positions);  // ArmAction has ended: it holds
    CHECK(later[0].positions[x_vertex].x == Approx(4.5f));
    // One of them alone leaves the other node at rest.
    auto box_only = posed_with(mesh, {0}, 1.0);
    CHECK(box_only[1].positions == mesh.parts[1].positions);

    // Two animations on one property: the later in the file wins.
    const Mesh clash = facet::load_gltf(two_actions_file(dir, true));
    auto lifted = posed_with(clash, {0, 2}, 1.0);
    CHECK(lifted[0].positions[x_vertex].x == Approx(1.0f));
    CHECK(lifted[0].positions[x_vertex].y == Approx(4.0f));

    const Mesh still =
        facet::load_gltf(single_mesh_file(dir.file("still.gltf"), kTriangle, json::object()));
    require_input_error([&] { facet::find_animations(still, {"all"}); }, "the file has none");
}
