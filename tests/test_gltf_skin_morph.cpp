// glTF skinning and morph targets (src/assets/gltf_pose.cpp, loaded by
// src/assets/gltf_rig_loader.cpp), on files built here with answers worked
// out by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
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

// How the skin file stores its joints and weights.
struct SkinFile {
    int joint_type = kUShort;
    int weight_type = kFloat;  // kUByte and kUShort are stored normalised
    bool two_sets = false;     // influences split over JOINTS_0/1 and WEIGHTS_0/1
    bool normals = true;       // without NORMAL, normals come from the faces
    bool bent = false;         // vertex 4 lifted off the plane, so flat normals split vertices
    bool morph = false;        // one morph target moves vertex 2 by +1 in x, weight 1
};

// The rest positions of the skin file's vertices, and their two influences
// (joint, weight, joint, weight), the weights before any scaling.
const std::vector<glm::vec3> kSkinPositions = {
    {0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {1, 2, 0}, {0, 1, 0}};
const std::vector<std::vector<float>> kInfluences = {
    {0, 1, 0, 0}, {0, 1, 0, 0}, {1, 1, 0, 0}, {0, 0.5f, 1, 0.5f}, {1, 1, 0, 0}};

glm::vec3 skin_position(int v, bool bent) {
    return v == 4 && bent ? glm::vec3(0, 1, 1) : kSkinPositions[v];
}

// Joint 0 at the origin (node 1) and its child joint 1 one unit up (node 2),
// which "bend" turns from 0 to 90 degrees about +Z over the first second.
// The mesh's node 0 is moved by +10 in x, which skinning must ignore.
Mesh skin_file(const TempDir& dir, const std::string& file, const SkinFile& o) {
    Gltf g;
    std::vector<float> positions, normals;
    std::vector<float> joints[2], weights[2];
    for (int v = 0; v < 5; ++v) {
        glm::vec3 p = skin_position(v, o.bent);
        positions.insert(positions.end(), {p.x, p.y, p.z});
        const glm::vec3 n = v == 2 ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        normals.insert(normals.end(), {n.x, n.y, n.z});
        const auto& in = kInfluences[v];
        if (o.two_sets) {
            joints[0].insert(joints[0].end(), {in[0], 0, 0, 0});
            weights[0].insert(weights[0].end(), {in[1], 0, 0, 0});
            joints[1].insert(joints[1].end(), {in[2], 0, 0, 0});
            weights[1].insert(weights[1].end(), {in[3], 0, 0, 0});
        } else {
            joints[0].insert(joints[0].end(), {in[0], in[2], 0, 0});
            weights[0].insert(weights[0].end(), {in[1], in[3], 0, 0});
        }
    }
    auto joint_accessor = [&](const std::vector<float>& values) {
        std::vector<uint8_t> bytes;
        for (float j : values) {
            if (o.joint_type == kUByte)
                bytes.push_back(static_cast<uint8_t>(j));
            else
                bytes.insert(bytes.end(), {static_cast<uint8_t>(j), 0});  // little-endian
        }
        return g.accessor(g.view(bytes), o.joint_type, values.size() / 4, "VEC4");
    };
    // Weights that do not sum to one: ×4 as floats, 1 -> 255 and 0.5 -> 128
    // as bytes (sum 256/255), 1 -> 65535 and 0.5 -> 32768 as shorts.
    auto weight_accessor = [&](const std::vector<float>& values) {
        if (o.weight_type == kFloat) {
            std::vector<float> scaled;
            for (float w : values) scaled.push_back(4 * w);
            return g.floats(scaled, "VEC4");
        }
        std::vector<uint8_t> bytes;
        for (float w : values) {
            if (o.weight_type == kUByte) {
                bytes.push_back(w == 1 ? 255 : w == 0.5f ? 128 : 0);
            } else {
                const uint16_t s = w == 1 ? 65535 : w == 0.5f ? 32768 : 0;
                bytes.insert(bytes.end(),
                             {static_cast<uint8_t>(s & 255), static_cast<uint8_t>(s >> 8)});
            }
        }
        return g.accessor(g.view(bytes), o.weight_type, values.size() / 4, "VEC4", 0, true);
    };
    json attributes = {{"POSITION", g.floats(positions, "VEC3")},
                       {"JOINTS_0", joint_accessor(joints[0])},
                       {"WEIGHTS_0", weight_accessor(weights[0])}};
    if (o.two_sets) {
        attributes["JOINTS_1"] = joint_accessor(joints[1]);
        attributes["WEIGHTS_1"] = weight_accessor(weights[1]);
    }
    if (o.normals) attributes["NORMAL"] = g.floats(normals, "VEC3");
    json primitive = {
        {"attributes", attributes},
        {"indices", g.indices(std::vector<uint16_t>{0, 1, 3, 0, 3, 2, 0, 1, 4}, kUShort)}};
    if (o.morph) {
        std::vector<float> deltas(15, 0.0f);
        deltas[6] = 1;  // vertex 2, x
        primitive["targets"] = json::array({{{"POSITION", g.floats(deltas, "VEC3")}}});
    }
    g.mesh(primitive);
    if (o.morph) g.doc["meshes"][0]["weights"] = {1.0};
    g.node({{"mesh", 0}, {"skin", 0}, {"translation", {10, 0, 0}}});
    g.node({{"children", {2}}});
    g.node({{"translation", {0, 1, 0}}});
    g.scene({0, 1});
    g.doc["skins"] = json::array(
        {{{"joints", {1, 2}},
          {"inverseBindMatrices",
           mat4s(g, concat({translation_matrix(0, 0, 0), translation_matrix(0, -1, 0)}))}}});
    add_channel(g, add_animation(g, "bend"), 2, "rotation", {0, 1},
                concat({z_turn(0), z_turn(90)}));
    return facet::load_gltf(g.write(dir.file(file)));
}

// Linear blend skinning of the skin file, written out independently: joint 0
// is the identity, joint 1 turns points about (0, 1) by `degrees`.
glm::dvec3 expected_skinned(glm::dvec3 p, const std::vector<float>& influence, double degrees) {
    const double a = degrees * M_PI / 180.0;
    const glm::dvec3 q = p - glm::dvec3(0, 1, 0);
    const glm::dvec3 turned =
        glm::dvec3(0, 1, 0) + glm::dvec3(std::cos(a) * q.x - std::sin(a) * q.y,
                                         std::sin(a) * q.x + std::cos(a) * q.y, q.z);
    glm::dvec3 sum(0.0);
    for (int k : {0, 2}) sum += double(influence[k + 1]) * (influence[k] == 0 ? p : turned);
    return sum;
}

// The skin file's vertex whose rest position is `rest`.
int skin_vertex(glm::vec3 rest, bool bent) {
    for (int v = 0; v < 5; ++v)
        if (glm::length(skin_position(v, bent) - rest) < 1e-6f) return v;
    FAIL("no skin vertex at (" << rest.x << ", " << rest.y << ", " << rest.z << ")");
    return 0;
}

}  // namespace

TEST_CASE("glTF two-joint skin bends vertices by the joint's angle", "[gltf][anim][skin]") {
    TempDir dir("gltf-skin");
    struct Variant {
        const char* name;
        SkinFile file;
    };
    for (const auto& variant :
         std::vector<Variant>{{"unsigned short joints, float weights", {kUShort, kFloat}},
                              {"unsigned byte joints, normalised byte weights", {kUByte, kUByte}},
                              {"normalised short weights", {kUShort, kUShort}},
                              {"influences in two sets", {kUByte, kFloat, true}}}) {
        DYNAMIC_SECTION(variant.name) {
            Mesh mesh = skin_file(dir, "skin.gltf", variant.file);
            REQUIRE(mesh.rig != nullptr);
            REQUIRE(mesh.rig->skins.size() == 1);
            const auto& part = mesh.parts[0];
            REQUIRE(part.positions.size() == 5);
            // The loaded parts are the skin at rest, where the node's own
            // +10 plays no part (§3.7.3.3).
            for (int v = 0; v < 5; ++v) require_vec3(part.positions[v], kSkinPositions[v]);

            // Without animation the joints are at their bind pose, and the
            // node's own +10 plays no part (§3.7.3.3).
            auto rest = posed(mesh, -1, 0);
            for (int v = 0; v < 5; ++v) require_vec3(rest[0].positions[v], kSkinPositions[v]);

            // A quarter turn: vertex 2, (0, 2) on joint 1 alone, turns about
            // (0, 1) to (-1, 1); its normal +X turns to +Y. Vertex 3, (1, 2)
            // half on each joint, goes halfway between (1, 2) and (-1, 2).
            auto quarter = posed(mesh, 0, 1);
            require_vec3(quarter[0].positions[2], {-1, 1, 0});
            require_vec3(quarter[0].normals[2], {0, 1, 0});
            require_vec3(quarter[0].positions[3], {0, 2, 0});
            require_vec3(quarter[0].positions[0], {0, 0, 0});
            require_vec3(quarter[0].positions[1], {1, 0, 0});
            require_vec3(quarter[0].positions[4], {0, 1, 0});
            for (int v : {0, 1, 3, 4}) require_vec3(quarter[0].normals[v], {0, 0, 1});
            CHECK_FALSE(quarter[0].winding_flipped);

            const float h = std::sqrt(0.5f);
            auto eighth = posed(mesh, 0, 0.5);
            require_vec3(eighth[0].positions[2], {-h, 1 + h, 0});
            require_vec3(eighth[0].normals[2], {h, h, 0});
            for (int v = 0; v < 5; ++v)
                require_vec3(eighth[0].positions[v],
                             glm::vec3(expected_skinned(kSkinPositions[v], kInfluences[v], 45)));
        }
    }
}

TEST_CASE("glTF skinned flat-shaded mesh keeps each split vertex's influences",
          "[gltf][anim][skin]") {
    TempDir dir("gltf-skin");
    // Without normals and with vertex 4 off the plane, the loader splits the
    // shared vertices 0 and 1 by face; each copy must still follow its joints.
    SkinFile file;
    file.normals = false;
    file.bent = true;
    Mesh mesh = skin_file(dir, "flat_skin.gltf", file);
    const auto& part = mesh.parts[0];
    REQUIRE(part.positions.size() > 5);
    for (double t : {0.0, 0.3, 1.0}) {
        INFO("t = " << t);
        auto parts = posed(mesh, 0, t);
        facet::MeshPart posed_part = part;
        posed_part.positions = parts[0].positions;
        posed_part.normals = parts[0].normals;
        for (size_t i = 0; i < part.positions.size(); ++i) {
            // The loaded parts are the skin at rest: the node's +10 plays no part.
            const int v = skin_vertex(part.positions[i], true);
            require_vec3(
                parts[0].positions[i],
                glm::vec3(expected_skinned(skin_position(v, true), kInfluences[v], 90 * t)));
        }
        require_normals_agree_with_winding(posed_part, 0.999f);
    }
}

TEST_CASE("glTF morph targets apply before skinning", "[gltf][anim][skin][morph]") {
    TempDir dir("gltf-skin");
    SkinFile file;
    file.morph = true;
    Mesh mesh = skin_file(dir, "morph_skin.gltf", file);
    // Vertex 2 morphs from (0, 2) to (1, 2), which joint 1's quarter turn
    // takes to (-1, 2). Morphing after skinning would give (0, 1).
    require_vec3(posed(mesh, 0, 1)[0].positions[2], {-1, 2, 0});
    require_vec3(posed(mesh, -1, 0)[0].positions[2], {1, 2, 0});
}

TEST_CASE("glTF morph targets at default and animated weights", "[gltf][anim][morph]") {
    TempDir dir("gltf-morph");
    // The triangle with normal +Z. Target 0 lifts vertex 2 by 2 in z and
    // tips every normal by +2 in x; target 1 moves only vertex 1, by
    // (0, 3, 0), through a sparse accessor (zeros plus substitutions).
    auto make = [&](const std::string& file, json node_weights) {
        Gltf g;
        const int target1_position = g.accessor(-1, kFloat, 3, "VEC3");
        g.sparse(target1_position, 1, g.view(bytes_of(std::vector<uint16_t>{1})), kUShort,
                 g.view(bytes_of(std::vector<float>{0, 3, 0})));
        json primitive = {{"attributes",
                           {{"POSITION", g.floats(kTriangle, "VEC3")},
                            {"NORMAL", g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3")}}},
                          {"targets",
                           {{{"POSITION", g.floats({0, 0, 0, 0, 0, 0, 0, 0, 2}, "VEC3")},
                             {"NORMAL", g.floats({2, 0, 0, 2, 0, 0, 2, 0, 0}, "VEC3")}},
                            {{"POSITION", target1_position}}}}};
        g.mesh(primitive);
        g.doc["meshes"][0]["weights"] = {0.5, 0};
        json node = {{"mesh", 0}};
        if (!node_weights.is_null()) node["weights"] = node_weights;
        g.scene({g.node(node)});
        add_channel(g, add_animation(g, "morph"), 0, "weights", {0, 2}, {0, 0, 1, 1});
        return facet::load_gltf(g.write(dir.file(file)));
    };
    SECTION("mesh default weights (0.5, 0)") {
        Mesh mesh = make("morph.gltf", nullptr);
        REQUIRE(mesh.rig->parts[0].morph_targets.size() == 2);
        const auto& part = mesh.parts[0];
        // The bake is the default weights' shape (§3.7.2.2), so a still
        // render and the bounds show what the author set.
        const float h = std::sqrt(0.5f);
        require_vec3(part.positions[2], {0, 1, 1});
        for (const auto& n : part.normals) require_vec3(n, {h, 0, h});
        auto rest = posed(mesh, -1, 0);
        CHECK(rest[0].positions == part.positions);
        CHECK(rest[0].normals == part.normals);
        require_vec3(rest[0].positions[0], {0, 0, 0});
        // The animation starts at weights (0, 0): the base shape, not the bake.
        auto start = posed(mesh, 0, 0);
        require_vec3(start[0].positions[2], {0, 1, 0});
        for (const auto& n : start[0].normals) require_vec3(n, {0, 0, 1});
        // Halfway: weights (0.5, 0.5).
        auto half = posed(mesh, 0, 1);
        require_vec3(half[0].positions[0], {0, 0, 0});
        require_vec3(half[0].positions[1], {1, 1.5f, 0});
        require_vec3(half[0].positions[2], {0, 1, 1});
        for (const auto& n : half[0].normals) require_vec3(n, {h, 0, h});
        // The end holds weights (1, 1).
        auto end = posed(mesh, 0, 5);
        require_vec3(end[0].positions[1], {1, 3, 0});
        require_vec3(end[0].positions[2], {0, 1, 2});
    }
    SECTION("node weights override the mesh's") {
        Mesh mesh = make("morph_node.gltf", {0, 1});
        auto rest = posed(mesh, -1, 0);
        require_vec3(rest[0].positions[1], {1, 3, 0});
        require_vec3(rest[0].positions[2], {0, 1, 0});
        for (const auto& n : rest[0].normals) require_vec3(n, {0, 0, 1});
    }
}
