// glTF animation, skin and morph data that a broken file gets wrong
// (src/assets/gltf_rig_loader.cpp): each must end in a facet::Error
// (invalid input) naming the file and the problem, never in a crash or in
// a pose that reads out of bounds.
#include <catch2/catch.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/gltf_pose.hpp"
#include "gltf_anim_support.hpp"

using namespace facet::test;
using nlohmann::json;

namespace {

// A valid file using everything: node 0 shows a skinned triangle with one
// morph target (mesh weight 0.5); nodes 1 and 2 are the joints; node 3 has
// a matrix. Animation 0 has three channels: node 2's translation (sampler
// 0, LINEAR), node 2's rotation (sampler 1, CUBICSPLINE) and node 0's
// weights (sampler 2, STEP).
void full_file(Gltf& g) {
    const int joints =
        g.accessor(g.view(bytes_of(std::vector<uint16_t>{0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0})),
                   kUShort, 3, "VEC4");
    const int weights = g.floats({1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0}, "VEC4");
    g.mesh({{"attributes",
             {{"POSITION", g.floats(kTriangle, "VEC3")},
              {"JOINTS_0", joints},
              {"WEIGHTS_0", weights}}},
            {"targets", {{{"POSITION", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")}}}}});
    g.doc["meshes"][0]["weights"] = {0.5};
    g.node({{"mesh", 0}, {"skin", 0}});
    g.node({{"children", {2}}});
    g.node({{"translation", {0, 1, 0}}});
    g.node({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
    g.scene({0, 1, 3});
    g.doc["skins"] = json::array(
        {{{"joints", {1, 2}},
          {"inverseBindMatrices",
           mat4s(g, concat({translation_matrix(0, 0, 0), translation_matrix(0, -1, 0)}))}}});
    const int a = add_animation(g, "all");
    add_channel(g, a, 2, "translation", {0, 1}, {0, 1, 0, 0, 2, 0});
    const std::vector<float> zero = {0, 0, 0, 0};
    add_channel(g, a, 2, "rotation", {0, 1},
                concat({zero, z_turn(0), zero, zero, z_turn(90), zero}), "CUBICSPLINE");
    add_channel(g, a, 0, "weights", {0, 1}, {0, 1}, "STEP");
}

struct Case {
    const char* name;
    const char* file;
    const char* problem;  // part of the message that names what is wrong
    std::function<void(Gltf&)> spoil;
};

json& sampler(Gltf& g, int s) {
    return g.doc["animations"][0]["samplers"][s];
}
json& channel(Gltf& g, int c) {
    return g.doc["animations"][0]["channels"][c];
}
json& attributes(Gltf& g) {
    return g.doc["meshes"][0]["primitives"][0]["attributes"];
}

int ushort_vec4(Gltf& g, const std::vector<uint16_t>& values) {
    return g.accessor(g.view(bytes_of(values)), kUShort, values.size() / 4, "VEC4");
}

}  // namespace

TEST_CASE("glTF the complete animated file loads and poses", "[gltf][anim]") {
    TempDir dir("gltf-anim-err");
    Gltf g;
    full_file(g);
    facet::Mesh mesh = facet::load_gltf(g.write(dir.file("full.gltf")));
    REQUIRE(mesh.rig != nullptr);
    CHECK(mesh.rig->animations.at(0).channels.size() == 3);
    CHECK(mesh.warnings.empty());
    for (double t : {0.0, 0.5, 1.0}) {
        auto parts = posed(mesh, 0, t);
        for (const auto& n : parts[0].normals) CHECK(glm::length(n) == Approx(1).margin(1e-5));
    }
}

TEST_CASE("glTF broken animation, skin and morph data are errors naming the file", "[gltf][anim]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<Case> cases = {
        // Channels.
        {"channel targets a missing node", "ch_node.gltf", "targets missing node 9",
         [](Gltf& g) { channel(g, 0)["target"]["node"] = 9; }},
        {"channel refers to a missing sampler", "ch_sampler.gltf", "missing sampler 5",
         [](Gltf& g) { channel(g, 0)["sampler"] = 5; }},
        {"one target animated twice", "ch_twice.gltf", "animated twice",
         [](Gltf& g) { g.doc["animations"][0]["channels"].push_back(channel(g, 0)); }},
        {"a node with a matrix animated", "ch_matrix.gltf", "has a matrix",
         [](Gltf& g) { channel(g, 0)["target"]["node"] = 3; }},
        {"weights of a node without morph targets", "ch_weights.gltf", "no mesh with morph targets",
         [](Gltf& g) { channel(g, 2)["target"]["node"] = 2; }},
        {"one sampler for a translation and a rotation", "ch_shared.gltf", "shares sampler 0",
         [](Gltf& g) {
             g.doc["animations"][0]["channels"].push_back(
                 {{"sampler", 0}, {"target", {{"node", 1}, {"path", "rotation"}}}});
         }},
        // Samplers.
        {"sampler input is a missing accessor", "s_input.gltf", "missing accessor 99",
         [](Gltf& g) { sampler(g, 0)["input"] = 99; }},
        {"keyframe times that repeat", "s_repeat.gltf", "do not increase at key 1",
         [](Gltf& g) {
             sampler(g, 0)["input"] = g.floats({1, 1}, "SCALAR");
         }},
        {"keyframe times that go back", "s_back.gltf", "do not increase at key 1",
         [](Gltf& g) {
             sampler(g, 0)["input"] = g.floats({1, 0.5f}, "SCALAR");
         }},
        {"negative keyframe time", "s_negative.gltf", "negative keyframe time",
         [](Gltf& g) {
             sampler(g, 0)["input"] = g.floats({-1, 1}, "SCALAR");
         }},
        {"NaN keyframe time", "s_nan_time.gltf", "not finite",
         [nan](Gltf& g) {
             sampler(g, 0)["input"] = g.floats({0, nan}, "SCALAR");
         }},
        {"no keyframes", "s_empty.gltf", "no keyframes",
         [](Gltf& g) { g.doc["accessors"][sampler(g, 0)["input"].get<int>()]["count"] = 0; }},
        {"NaN keyframe value", "s_nan_value.gltf", "not finite",
         [nan](Gltf& g) {
             sampler(g, 0)["output"] = g.floats({0, nan, 0, 0, 2, 0}, "VEC3");
         }},
        {"more values than keyframes", "s_count.gltf", "values for 2 keyframes",
         [](Gltf& g) {
             sampler(g, 0)["output"] = g.floats({0, 0, 0, 1, 1, 1, 2, 2, 2}, "VEC3");
         }},
        {"cubic spline without tangents", "s_cubic_count.gltf", "values for 2 keyframes",
         [](Gltf& g) {
             sampler(g, 1)["output"] = g.floats(concat({z_turn(0), z_turn(90)}), "VEC4");
         }},
        {"rotation given as VEC3", "s_vec3.gltf", "3 components per element, expected 4",
         [](Gltf& g) { sampler(g, 1)["output"] = sampler(g, 0)["output"]; }},
        {"unknown interpolation", "s_interp.gltf", "unknown interpolation 'SMOOTH'",
         [](Gltf& g) { sampler(g, 0)["interpolation"] = "SMOOTH"; }},
        {"cubic spline with one keyframe", "s_cubic_one.gltf", "fewer than two keyframes",
         [](Gltf& g) {
             sampler(g, 1)["input"] = g.floats({0}, "SCALAR");
             sampler(g, 1)["output"] =
                 g.floats(concat({{0, 0, 0, 0}, z_turn(0), {0, 0, 0, 0}}), "VEC4");
         }},
        {"rotation keyframe of length zero", "s_zero_quat.gltf", "rotation at key 1 is zero",
         [](Gltf& g) {
             sampler(g, 1)["output"] = g.floats(concat({{0, 0, 0, 0},
                                                        z_turn(0),
                                                        {0, 0, 0, 0},
                                                        {0, 0, 0, 0},
                                                        {0, 0, 0, 0},
                                                        {0, 0, 0, 0}}),
                                                "VEC4");
         }},
        {"weights values for the wrong number of targets", "s_weights.gltf",
         "values for 2 keyframes",
         [](Gltf& g) {
             sampler(g, 2)["output"] = g.floats({0, 1, 0, 1}, "SCALAR");
         }},
        // Nodes.
        {"node rotation of length zero", "n_zero_quat.gltf", "rotation of length zero",
         [](Gltf& g) {
             g.doc["nodes"][2]["rotation"] = {0, 0, 0, 0};
         }},
        {"node weights for the wrong number of targets", "n_weights.gltf",
         "gives 2 morph weights, but its mesh has 1",
         [](Gltf& g) {
             g.doc["nodes"][0]["weights"] = {1, 2};
         }},
        {"mesh weights for the wrong number of targets", "m_weights.gltf", "gives 3 morph weights",
         [](Gltf& g) {
             g.doc["meshes"][0]["weights"] = {1, 2, 3};
         }},
        {"node weights without a mesh", "n_weights_nomesh.gltf", "morph weights but no mesh",
         [](Gltf& g) { g.doc["nodes"][2]["weights"] = {1}; }},
        {"cycle among nodes outside the scene", "n_cycle.gltf", "cycle",
         [](Gltf& g) {
             g.node({{"children", {5}}});
             g.node({{"children", {4}}});
         }},
        {"child that does not exist", "n_child.gltf", "missing child 9",
         [](Gltf& g) {
             g.node({{"children", {9}}});
         }},
        // Skins.
        {"skin joint that does not exist", "k_joint.gltf", "missing joint node 7",
         [](Gltf& g) {
             g.doc["skins"][0]["joints"] = {1, 7};
         }},
        {"skin without joints", "k_empty.gltf", "has no joints",
         [](Gltf& g) { g.doc["skins"][0]["joints"] = json::array(); }},
        {"fewer inverse bind matrices than joints", "k_ibm.gltf",
         "1 inverse bind matrices for 2 joints",
         [](Gltf& g) {
             g.doc["skins"][0]["inverseBindMatrices"] = mat4s(g, translation_matrix(0, 0, 0));
         }},
        {"inverse bind matrices that are not MAT4", "k_ibm_type.gltf", "components per element",
         [](Gltf& g) { g.doc["skins"][0]["inverseBindMatrices"] = attributes(g)["POSITION"]; }},
        {"node refers to a missing skin", "k_node.gltf", "missing skin 4",
         [](Gltf& g) { g.doc["nodes"][0]["skin"] = 4; }},
        {"joint index past the skin's joints", "k_index.gltf", "uses joint 2 of a skin with 2",
         [](Gltf& g) {
             attributes(g)["JOINTS_0"] = ushort_vec4(g, {0, 1, 0, 0, 0, 2, 0, 0, 1, 0, 0, 0});
         }},
        {"float joint indices", "k_float.gltf", "must be unsigned bytes or shorts",
         [](Gltf& g) { attributes(g)["JOINTS_0"] = attributes(g)["WEIGHTS_0"]; }},
        {"weights as signed shorts", "k_wtype.gltf", "must be floats or normalised unsigned",
         [](Gltf& g) {
             attributes(g)["WEIGHTS_0"] = g.accessor(
                 g.view(bytes_of(std::vector<int16_t>(12, 100))), kShort, 3, "VEC4", 0, true);
         }},
        {"fewer weights than vertices", "k_wcount.gltf", "count differs from POSITION count",
         [](Gltf& g) {
             attributes(g)["WEIGHTS_0"] = g.floats({1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
         }},
        {"negative weight", "k_negative.gltf", "negative joint weight",
         [](Gltf& g) {
             attributes(g)["WEIGHTS_0"] =
                 g.floats({1, 0, 0, 0, 1.5f, -0.5f, 0, 0, 1, 0, 0, 0}, "VEC4");
         }},
        {"weights summing to zero", "k_zero.gltf", "summing to 0",
         [](Gltf& g) {
             attributes(g)["WEIGHTS_0"] = g.floats({1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
         }},
        {"skinned mesh without joints", "k_nojoints.gltf", "has no JOINTS_0 and WEIGHTS_0",
         [](Gltf& g) {
             attributes(g).erase("JOINTS_0");
             attributes(g).erase("WEIGHTS_0");
         }},
        {"joints without weights", "k_noweights.gltf", "no matching WEIGHTS_0",
         [](Gltf& g) { attributes(g).erase("WEIGHTS_0"); }},
        // Morph targets.
        {"morph target with too few deltas", "t_count.gltf", "count differs from POSITION count",
         [](Gltf& g) {
             g.doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] =
                 g.floats({0, 0, 1}, "VEC3");
         }},
        {"primitives with different numbers of targets", "t_prims.gltf",
         "different numbers of morph targets",
         [](Gltf& g) {
             g.doc["meshes"][0]["primitives"].push_back(
                 {{"attributes", {{"POSITION", attributes(g)["POSITION"]}}}});
         }},
    };
    TempDir dir("gltf-anim-err");
    for (const auto& c : cases) {
        DYNAMIC_SECTION(c.name) {
            Gltf g;
            full_file(g);
            c.spoil(g);
            const std::string path = g.write(dir.file(c.file));
            require_input_error([&] { facet::load_gltf(path); }, c.file);
            require_input_error([&] { facet::load_gltf(path); }, c.problem);
        }
    }
}

TEST_CASE("glTF channels for other targets are left out with a warning", "[gltf][anim]") {
    TempDir dir("gltf-anim-err");
    for (const auto& [name, target] : std::vector<std::pair<std::string, json>>{
             {"no node", {{"path", "translation"}}},
             {"extension path", {{"node", 2}, {"path", "pointer"}}}}) {
        DYNAMIC_SECTION(name) {
            Gltf g;
            full_file(g);
            channel(g, 0)["target"] = target;
            // The left-out channel's sampler ends last, but no longer counts.
            sampler(g, 0)["input"] = g.floats({0, 5}, "SCALAR");
            facet::Mesh mesh = facet::load_gltf(g.write(dir.file("other.gltf")));
            CHECK(mesh.rig->animations[0].channels.size() == 2);
            // tinygltf itself drops a channel without a node, silently.
            if (name == "extension path") {
                REQUIRE(mesh.warnings.size() == 1);
                CHECK_THAT(mesh.warnings[0].message, Catch::Contains("channel 0"));
            }
            CHECK(facet::animation_duration(mesh, 0) == 1.0);
        }
    }
}
