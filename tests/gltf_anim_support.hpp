#pragma once
// Helpers for the glTF animation tests: writing animations, skins and morph
// targets with the Gltf builder of asset_support.hpp, and posing the loaded
// mesh at one time.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "asset_support.hpp"
#include "assets/gltf_pose.hpp"

namespace facet::test {

// Quaternion (x, y, z, w) of `degrees` about +Z.
inline std::vector<float> z_turn(double degrees) {
    const double half = degrees * M_PI / 360.0;
    return {0, 0, static_cast<float>(std::sin(half)), static_cast<float>(std::cos(half))};
}

inline std::vector<float> concat(std::vector<std::vector<float>> lists) {
    std::vector<float> out;
    for (const auto& l : lists) out.insert(out.end(), l.begin(), l.end());
    return out;
}

// A column-major MAT4 accessor holding `values` (16 per matrix).
inline int mat4s(Gltf& g, const std::vector<float>& values) {
    return g.accessor(g.view(bytes_of(values)), kFloat, values.size() / 16, "MAT4");
}

// The column-major translation matrix, as glTF stores it.
inline std::vector<float> translation_matrix(float x, float y, float z) {
    return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1};
}

// Starts animation `name` in the document and returns its index.
inline int add_animation(Gltf& g, const std::string& name) {
    g.doc["animations"].push_back({{"name", name},
                                   {"samplers", nlohmann::json::array()},
                                   {"channels", nlohmann::json::array()}});
    return static_cast<int>(g.doc["animations"].size()) - 1;
}

// Adds a sampler (times, values, interpolation) and a channel driving `path`
// of `node` to animation `animation`. Values are VEC3 for translation and
// scale, VEC4 for rotation and SCALAR for weights, as §3.11 wants.
inline void add_channel(Gltf& g, int animation, int node, const std::string& path,
                        const std::vector<float>& times, const std::vector<float>& values,
                        const std::string& interpolation = "LINEAR") {
    const std::string type = path == "rotation" ? "VEC4" : path == "weights" ? "SCALAR" : "VEC3";
    auto& anim = g.doc["animations"][animation];
    anim["samplers"].push_back({{"input", g.floats(times, "SCALAR")},
                                {"output", g.floats(values, type)},
                                {"interpolation", interpolation}});
    anim["channels"].push_back(
        {{"sampler", anim["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
}

// Two nodes showing one triangle each, "Box" at the origin and "Arm" at
// z = 5, as a scene of two objects (Blender writes one action per object).
struct BoxAndArm {
    int box, arm;
};
inline BoxAndArm box_and_arm(Gltf& g) {
    const int triangle = g.mesh({{"attributes", {{"POSITION", g.floats(kTriangle, "VEC3")}}}});
    const int box = g.node({{"name", "Box"}, {"mesh", triangle}});
    const int arm = g.node({{"name", "Arm"}, {"mesh", triangle}, {"translation", {0, 0, 5}}});
    g.scene({box, arm});
    return {box, arm};
}

// The parts of `mesh` posed at `seconds` into `animation`.
inline std::vector<PosedPart> posed(const Mesh& mesh, int animation, double seconds) {
    std::vector<PosedPart> out;
    pose_mesh(mesh, animation, seconds, out);
    REQUIRE(out.size() == mesh.parts.size());
    for (size_t p = 0; p < out.size(); ++p) {
        REQUIRE(out[p].positions.size() == mesh.parts[p].positions.size());
        REQUIRE(out[p].normals.size() == mesh.parts[p].positions.size());
    }
    return out;
}

// The parts of `mesh` posed at `seconds` into several animations at once.
inline std::vector<PosedPart> posed_with(const Mesh& mesh, const std::vector<int>& animations,
                                         double seconds) {
    std::vector<PosedPart> out;
    pose_mesh(mesh, animations, seconds, out);
    REQUIRE(out.size() == mesh.parts.size());
    return out;
}

inline Bounds bounds_of(const std::vector<PosedPart>& parts) {
    Bounds b;
    for (const auto& part : parts)
        for (const auto& p : part.positions) b.add(p);
    return b;
}

}  // namespace facet::test
