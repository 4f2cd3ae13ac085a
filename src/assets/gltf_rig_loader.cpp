// Reads what poses a glTF mesh: the node tree (glTF 2.0 §3.5), skins
// (§3.7.3), morph targets (§3.7.2.2) and animations (§3.11). Everything a
// broken file could get wrong is checked here, once, so posing never needs
// to check an index or a count.
#include "assets/gltf_rig_loader.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "assets/gltf_accessors.hpp"
#include "core/enum_names.hpp"

namespace facet::gltf_detail {
namespace {

std::string node_name(int index) {
    return "node " + std::to_string(index);
}

bool all_finite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// All primitives of a mesh must have the same number of morph targets
// (§3.7.2.2), because the node's weights apply to every one of them.
size_t morph_target_count(const tinygltf::Mesh& mesh, int mesh_index, const std::string& path) {
    size_t count = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    for (const auto& prim : mesh.primitives)
        if (prim.targets.size() != count)
            bad(path, "mesh " + std::to_string(mesh_index) +
                          ": primitives have different numbers of morph targets");
    return count;
}

RigNode rest_node(const tinygltf::Model& model, int index, const std::string& path) {
    const tinygltf::Node& node = model.nodes[index];
    const std::string what = node_name(index);
    RigNode out;
    out.name = node.name.empty() ? "node" + std::to_string(index) : node.name;
    for (const auto* field :
         {&node.matrix, &node.translation, &node.rotation, &node.scale, &node.weights})
        if (!all_finite(*field)) bad(path, what + " has a transform or weight that is not finite");
    // The same fields, with the same sizes, that the rest-pose bake reads.
    if (node.matrix.size() == 16) {
        out.has_matrix = true;
        out.matrix = glm::make_mat4(node.matrix.data());  // column-major, as glTF stores it
    }
    if (node.translation.size() == 3)
        out.translation = {node.translation[0], node.translation[1], node.translation[2]};
    if (node.rotation.size() == 4) {
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (glm::length(q) < 1e-12) bad(path, what + " has a rotation of length zero");
        out.rotation = glm::normalize(q);
    }
    if (node.scale.size() == 3) out.scale = {node.scale[0], node.scale[1], node.scale[2]};

    if (node.mesh >= 0 && static_cast<size_t>(node.mesh) < model.meshes.size()) {
        const tinygltf::Mesh& mesh = model.meshes[node.mesh];
        const size_t targets = morph_target_count(mesh, node.mesh, path);
        if (!all_finite(mesh.weights))
            bad(path, "mesh " + std::to_string(node.mesh) + " has a weight that is not finite");
        // §3.7.2.2: the node's weights override the mesh's defaults.
        const auto& defaults = node.weights.empty() ? mesh.weights : node.weights;
        if (!defaults.empty() && defaults.size() != targets)
            bad(path, what + " gives " + std::to_string(defaults.size()) +
                          " morph weights, but its mesh has " + std::to_string(targets) +
                          " morph targets");
        out.weights = defaults.empty() ? std::vector<double>(targets, 0.0) : defaults;
    } else if (!node.weights.empty()) {
        bad(path, what + " has morph weights but no mesh");
    }
    return out;
}

// Parents from the children lists, and an order that puts every parent
// before its children. Nodes that no root reaches lie on a cycle (each node
// has at most one parent), which §3.5.3 forbids.
void read_hierarchy(const tinygltf::Model& model, const std::string& path, MeshRig& rig) {
    const size_t n = model.nodes.size();
    for (size_t i = 0; i < n; ++i)
        for (int child : model.nodes[i].children) {
            if (child < 0 || static_cast<size_t>(child) >= n)
                bad(path,
                    node_name(static_cast<int>(i)) + " has missing child " + std::to_string(child));
            if (rig.nodes[child].parent >= 0 || static_cast<size_t>(child) == i)
                bad(path, "node " + std::to_string(child) + " has more than one parent");
            rig.nodes[child].parent = static_cast<int>(i);
        }
    for (size_t i = 0; i < n; ++i)
        if (rig.nodes[i].parent < 0) rig.node_order.push_back(static_cast<int>(i));
    for (size_t next = 0; next < rig.node_order.size(); ++next)
        for (int child : model.nodes[rig.node_order[next]].children)
            rig.node_order.push_back(child);
    if (rig.node_order.size() != n) {
        std::vector<bool> placed(n, false);
        for (int i : rig.node_order) placed[i] = true;
        const auto first = std::find(placed.begin(), placed.end(), false) - placed.begin();
        bad(path, "node hierarchy has a cycle through node " + std::to_string(first));
    }
}

void read_skins(const tinygltf::Model& model, const std::string& path, MeshRig& rig) {
    for (size_t s = 0; s < model.skins.size(); ++s) {
        const tinygltf::Skin& skin = model.skins[s];
        const std::string what = "skin " + std::to_string(s);
        if (skin.joints.empty()) bad(path, what + " has no joints");
        RigSkin out;
        for (int joint : skin.joints) {
            if (joint < 0 || static_cast<size_t>(joint) >= model.nodes.size())
                bad(path, what + " refers to missing joint node " + std::to_string(joint));
            out.joints.push_back(joint);
        }
        // §3.7.3.1: without inverse bind matrices, each is the identity.
        out.inverse_bind.assign(skin.joints.size(), glm::dmat4(1.0));
        if (skin.inverseBindMatrices >= 0) {
            std::vector<float> m = read_floats(model, skin.inverseBindMatrices, 16, path,
                                               what + " inverseBindMatrices");
            if (m.size() / 16 < skin.joints.size())
                bad(path, what + " has " + std::to_string(m.size() / 16) +
                              " inverse bind matrices for " + std::to_string(skin.joints.size()) +
                              " joints");
            for (size_t j = 0; j < skin.joints.size(); ++j)
                out.inverse_bind[j] = glm::dmat4(glm::make_mat4(m.data() + 16 * j));
        }
        rig.skins.push_back(std::move(out));
    }
}

// The names of §3.11.1's paths and §5.24's interpolations.
constexpr EnumName<RigChannelPath> kChannelPaths[] = {{RigChannelPath::translation, "translation"},
                                                      {RigChannelPath::rotation, "rotation"},
                                                      {RigChannelPath::scale, "scale"},
                                                      {RigChannelPath::weights, "weights"}};
constexpr EnumName<RigInterpolation> kInterpolations[] = {
    {RigInterpolation::linear, "LINEAR"},
    {RigInterpolation::step, "STEP"},
    {RigInterpolation::cubic_spline, "CUBICSPLINE"}};

RigInterpolation interpolation_of(const std::string& name, const std::string& path,
                                  const std::string& what) {
    if (name.empty()) return RigInterpolation::linear;  // the default
    if (const std::optional<RigInterpolation> known = value_of(kInterpolations, name))
        return *known;
    bad(path, what + " has unknown interpolation '" + name + "'");
}

// Channels may share a sampler when they read its output the same way:
// translations and scales are both plain VEC3.
RigChannelPath same_values(RigChannelPath p) {
    return p == RigChannelPath::scale ? RigChannelPath::translation : p;
}

// The keyframe times of a sampler: §3.11.2 wants at least one, each one
// finite, not negative, and each later than the one before.
std::vector<double> read_times(const tinygltf::Model& model, int accessor, const std::string& path,
                               const std::string& what) {
    std::vector<float> times = read_floats(model, accessor, 1, path, what + " input");
    if (times.empty()) bad(path, what + " has no keyframes");
    if (times[0] < 0) bad(path, what + " has a negative keyframe time");
    for (size_t k = 1; k < times.size(); ++k)
        if (!(times[k] > times[k - 1]))
            bad(path, what + " keyframe times do not increase at key " + std::to_string(k) + " (" +
                          std::to_string(times[k - 1]) + " then " + std::to_string(times[k]) + ")");
    return {times.begin(), times.end()};
}

// Reads a sampler's output for a channel that animates `components` values
// per key, and checks it holds exactly one element (three for a cubic
// spline) per key.
void read_values(const tinygltf::Model& model, int accessor, RigChannelPath target, int components,
                 const std::string& path, const std::string& what, RigSampler& sampler) {
    const bool cubic = sampler.interpolation == RigInterpolation::cubic_spline;
    if (cubic && sampler.times.size() < 2)
        bad(path, what + " is a cubic spline with fewer than two keyframes");
    // Weights are a SCALAR accessor with one value per target per key (§3.11.2).
    const int per_element = target == RigChannelPath::weights ? 1 : components;
    std::vector<float> values = read_floats(model, accessor, per_element, path, what + " output");
    const size_t expected = sampler.times.size() * (cubic ? 3 : 1) * components;
    if (values.size() != expected)
        bad(path, what + " output has " + std::to_string(values.size()) + " values for " +
                      std::to_string(sampler.times.size()) + " keyframes (expected " +
                      std::to_string(expected) + ")");
    sampler.values.assign(values.begin(), values.end());
    sampler.components = components;
    if (target != RigChannelPath::rotation) return;
    // Rotations must be unit quaternions; values stored as normalised
    // integers are only close, so every key value (not the cubic tangents,
    // which are derivatives) is normalised here.
    const size_t stride = cubic ? 3 : 1, offset = cubic ? 1 : 0;
    for (size_t k = 0; k < sampler.times.size(); ++k) {
        double* q = sampler.values.data() + 4 * (k * stride + offset);
        const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(len > 1e-6)) bad(path, what + " rotation at key " + std::to_string(k) + " is zero");
        for (int c = 0; c < 4; ++c) q[c] /= len;
    }
}

RigAnimation read_animation(const tinygltf::Model& model, int index, const MeshRig& rig,
                            const std::string& path, Warnings& warnings) {
    const tinygltf::Animation& anim = model.animations[index];
    RigAnimation out;
    out.name = anim.name.empty() ? "animation" + std::to_string(index) : anim.name;
    const std::string what = "animation '" + out.name + "'";
    for (size_t s = 0; s < anim.samplers.size(); ++s) {
        const std::string sw = what + " sampler " + std::to_string(s);
        RigSampler sampler;
        sampler.interpolation = interpolation_of(anim.samplers[s].interpolation, path, sw);
        sampler.times = read_times(model, anim.samplers[s].input, path, sw);
        out.samplers.push_back(std::move(sampler));
    }
    std::set<std::pair<int, RigChannelPath>> targets;
    std::vector<RigChannelPath> sampler_target(anim.samplers.size());
    std::vector<bool> sampler_used(anim.samplers.size(), false);
    for (size_t c = 0; c < anim.channels.size(); ++c) {
        const tinygltf::AnimationChannel& ch = anim.channels[c];
        const std::string cw = what + " channel " + std::to_string(c);
        const std::optional<RigChannelPath> known =
            value_of(kChannelPaths, ch.target_path);  // else an extension's
        // §3.11.1: without a node the target is defined by an extension;
        // other paths come from extensions too. Neither moves a mesh here.
        if (ch.target_node < 0 || !known) {
            warnings.push_back(
                file_warning(path, cw + " targets '" + ch.target_path +
                                       "', not a node's transform or weights; ignored"));
            continue;
        }
        if (static_cast<size_t>(ch.target_node) >= rig.nodes.size())
            bad(path, cw + " targets missing node " + std::to_string(ch.target_node));
        if (ch.sampler < 0 || static_cast<size_t>(ch.sampler) >= anim.samplers.size())
            bad(path, cw + " refers to missing sampler " + std::to_string(ch.sampler));
        RigChannel channel{ch.target_node, *known, ch.sampler};
        const RigNode& node = rig.nodes[channel.node];
        const std::string target =
            node_name(channel.node) + " " + std::string(name_of(kChannelPaths, channel.path));
        if (!targets.insert({channel.node, channel.path}).second)
            bad(path, cw + ": " + target + " is animated twice");
        if (channel.path != RigChannelPath::weights && node.has_matrix)
            bad(path, cw + " animates " + node_name(channel.node) +
                          ", which has a matrix (only translation, rotation and scale "
                          "can be animated)");
        int components = channel.path == RigChannelPath::rotation ? 4 : 3;
        if (channel.path == RigChannelPath::weights) {
            if (node.weights.empty())
                bad(path, cw + " animates the weights of " + node_name(channel.node) +
                              ", which shows no mesh with morph targets");
            components = static_cast<int>(node.weights.size());
        }
        RigSampler& sampler = out.samplers[ch.sampler];
        if (!sampler_used[ch.sampler]) {
            read_values(model, anim.samplers[ch.sampler].output, channel.path, components, path,
                        what + " sampler " + std::to_string(ch.sampler), sampler);
            sampler_used[ch.sampler] = true;
            sampler_target[ch.sampler] = channel.path;
        } else if (sampler.components != components ||
                   same_values(sampler_target[ch.sampler]) != same_values(channel.path)) {
            bad(path, cw + " shares sampler " + std::to_string(ch.sampler) +
                          " with a channel that animates a different kind of value");
        }
        out.channels.push_back(channel);
    }
    // The animation lasts until its last keyframe; samplers no channel uses
    // do not count.
    for (size_t s = 0; s < out.samplers.size(); ++s)
        if (sampler_used[s]) out.duration = std::max(out.duration, out.samplers[s].times.back());
    return out;
}

}  // namespace

bool has_rig_data(const tinygltf::Model& model) {
    if (!model.animations.empty() || !model.skins.empty()) return true;
    for (const auto& mesh : model.meshes)
        for (const auto& prim : mesh.primitives)
            if (!prim.targets.empty()) return true;
    return false;
}

void read_rig_nodes_and_animations(const tinygltf::Model& model, const std::string& path,
                                   MeshRig& rig, Warnings& warnings) {
    for (size_t i = 0; i < model.nodes.size(); ++i)
        rig.nodes.push_back(rest_node(model, static_cast<int>(i), path));
    read_hierarchy(model, path, rig);
    read_skins(model, path, rig);
    for (size_t a = 0; a < model.animations.size(); ++a)
        rig.animations.push_back(read_animation(model, static_cast<int>(a), rig, path, warnings));
}

void read_part_skin_and_morph(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                              const MeshRig& rig, const std::string& path, const std::string& what,
                              RigPart& part) {
    const size_t count = part.positions.size();
    if (part.skin >= 0) {
        if (static_cast<size_t>(part.skin) >= rig.skins.size())
            bad(path,
                node_name(part.node) + " refers to missing skin " + std::to_string(part.skin));
        const size_t joint_count = rig.skins[part.skin].joints.size();
        // §3.7.3.2: influences come in sets of four, JOINTS_n with WEIGHTS_n.
        std::vector<std::vector<float>> set_joints, set_weights;
        for (int set = 0;; ++set) {
            auto joints_it = primitive.attributes.find("JOINTS_" + std::to_string(set));
            if (joints_it == primitive.attributes.end()) break;
            auto weights_it = primitive.attributes.find("WEIGHTS_" + std::to_string(set));
            const std::string jw = what + " JOINTS_" + std::to_string(set);
            const std::string ww = what + " WEIGHTS_" + std::to_string(set);
            if (weights_it == primitive.attributes.end())
                bad(path, jw + " has no matching WEIGHTS_" + std::to_string(set));
            const auto& jacc = accessor_at(model, joints_it->second, path, jw);
            if ((jacc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 jacc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ||
                jacc.normalized)
                bad(path, jw + " must be unsigned bytes or shorts, not normalised");
            const auto& wacc = accessor_at(model, weights_it->second, path, ww);
            const bool unsigned_int = wacc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                      wacc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
            if (wacc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
                !(unsigned_int && wacc.normalized))
                bad(path, ww + " must be floats or normalised unsigned bytes or shorts");
            set_joints.push_back(read_floats(model, joints_it->second, 4, path, jw));
            set_weights.push_back(read_floats(model, weights_it->second, 4, path, ww));
            if (set_joints.back().size() != 4 * count || set_weights.back().size() != 4 * count)
                bad(path, jw + " or WEIGHTS_" + std::to_string(set) +
                              " count differs from POSITION count");
        }
        if (set_joints.empty())
            bad(path, what + " is shown by " + node_name(part.node) +
                          " with a skin, but has no JOINTS_0 and WEIGHTS_0");
        part.influences = 4 * static_cast<int>(set_joints.size());
        part.joints.resize(count * part.influences);
        part.weights.resize(count * part.influences);
        for (size_t v = 0; v < count; ++v) {
            const size_t first = v * part.influences;
            double sum = 0;
            for (size_t set = 0; set < set_joints.size(); ++set)
                for (size_t k = 0; k < 4; ++k) {
                    const float joint = set_joints[set][4 * v + k];
                    const float weight = set_weights[set][4 * v + k];
                    // §3.7.3.2: every joint index must name a joint of the skin.
                    if (!(joint < static_cast<float>(joint_count)))
                        bad(path, what + ": vertex " + std::to_string(v) + " uses joint " +
                                      std::to_string(static_cast<long>(joint)) +
                                      " of a skin with " + std::to_string(joint_count) + " joints");
                    if (weight < 0)
                        bad(path, what + ": vertex " + std::to_string(v) +
                                      " has a negative joint weight");
                    part.joints[first + 4 * set + k] = static_cast<uint16_t>(joint);
                    part.weights[first + 4 * set + k] = weight;
                    sum += weight;
                }
            // The weights should sum to one; exporters that quantise them
            // often miss slightly, so every vertex is rescaled.
            if (!(sum > 0))
                bad(path,
                    what + ": vertex " + std::to_string(v) + " has joint weights summing to 0");
            for (int k = 0; k < part.influences; ++k)
                part.weights[first + k] = static_cast<float>(part.weights[first + k] / sum);
        }
    }

    const size_t targets = rig.nodes[part.node].weights.size();
    if (primitive.targets.size() != targets)
        bad(path, what + " has " + std::to_string(primitive.targets.size()) +
                      " morph targets, but its node has " + std::to_string(targets) + " weights");
    for (size_t t = 0; t < targets; ++t) {
        RigMorphTarget target;
        const std::string tw = what + " morph target " + std::to_string(t);
        for (const auto& [name, deltas] : {std::pair{"POSITION", &target.position_deltas},
                                           {"NORMAL", &target.normal_deltas},
                                           {"TANGENT", &target.tangent_deltas}}) {
            auto it = primitive.targets[t].find(name);
            if (it == primitive.targets[t].end()) continue;
            std::vector<float> d = read_floats(model, it->second, 3, path, tw + " " + name);
            if (d.size() != 3 * count)
                bad(path, tw + " " + name + " count differs from POSITION count");
            for (size_t v = 0; v < count; ++v)
                deltas->push_back({d[3 * v], d[3 * v + 1], d[3 * v + 2]});
        }
        part.morph_targets.push_back(std::move(target));
    }
}

}  // namespace facet::gltf_detail
