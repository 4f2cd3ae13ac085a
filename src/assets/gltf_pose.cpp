// Posing glTF meshes: keyframe sampling (glTF 2.0 §3.11 and Appendix C),
// node transforms (§3.5.3), morph targets (§3.7.2.2) and skinning (§3.7.3).
// Everything is computed in double and rounded to float once at the end, so
// long hierarchies and large joint counts do not accumulate float error; the
// build forbids fast-math and contraction, so results are reproducible.
#include "assets/gltf_pose.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/error.hpp"

namespace facet {
namespace {

// Local transform of one node while posing.
struct NodeTrs {
    glm::dvec3 translation;
    glm::dquat rotation;
    glm::dvec3 scale;
};

// Quaternions are stored x, y, z, w as glTF writes them; glm takes w first.
glm::dquat quat_at(const double* q) {
    return glm::dquat(q[3], q[0], q[1], q[2]);
}

// Spherical linear interpolation along the shorter arc (Appendix C): q and
// -q are the same rotation, so the second key is negated when the two point
// into opposite half-spaces.
glm::dquat slerp_shortest(const glm::dquat& a, glm::dquat b, double u) {
    double d = glm::dot(a, b);
    if (d < 0) {
        b = -b;
        d = -d;
    }
    glm::dquat q;
    if (d > 1.0 - 1e-12) {
        // Nearly equal keys: sin(angle) ~ 0, and the straight line is exact enough.
        q = a * (1.0 - u) + b * u;
    } else {
        const double angle = std::acos(d);
        const double s = std::sin(angle);
        q = a * (std::sin((1.0 - u) * angle) / s) + b * (std::sin(u * angle) / s);
    }
    return glm::normalize(q);
}

// Writes the sampler's `components` values at `time` into `out`.
// Before the first key and after the last, the end keys hold (§3.11.2).
void sample(const RigSampler& s, double time, bool rotation, double* out) {
    const int c = s.components;
    const bool cubic = s.interpolation == RigInterpolation::cubic_spline;
    // Element e of key k: for a cubic spline 0 = in-tangent, 1 = value,
    // 2 = out-tangent; otherwise there is only the value.
    auto at = [&](size_t k, int e) { return s.values.data() + (cubic ? 3 * k + e : k) * c; };
    const size_t keys = s.times.size();
    size_t k = 0;
    double u = 0;
    if (time >= s.times.back()) {
        k = keys - 1;
    } else if (time > s.times.front()) {
        const auto next = std::upper_bound(s.times.begin(), s.times.end(), time);
        k = static_cast<size_t>(next - s.times.begin()) - 1;
        u = (time - s.times[k]) / (s.times[k + 1] - s.times[k]);
    }
    const double* v0 = at(k, 1);
    if (u == 0 || s.interpolation == RigInterpolation::step) {
        std::copy(v0, v0 + c, out);
        return;
    }
    const double* v1 = at(k + 1, 1);
    if (s.interpolation == RigInterpolation::linear) {
        if (rotation) {
            glm::dquat q = slerp_shortest(quat_at(v0), quat_at(v1), u);
            out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
        } else {
            for (int i = 0; i < c; ++i) out[i] = v0[i] * (1.0 - u) + v1[i] * u;
        }
        return;
    }
    // Cubic Hermite spline (Appendix C): the stored tangents are per second,
    // so they are scaled by the length of the key interval.
    const double dt = s.times[k + 1] - s.times[k];
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
    const double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    const double* out_tangent = at(k, 2);
    const double* in_tangent = at(k + 1, 0);
    for (int i = 0; i < c; ++i)
        out[i] = h00 * v0[i] + h10 * dt * out_tangent[i] + h01 * v1[i] + h11 * dt * in_tangent[i];
    if (rotation) {
        // The spline leaves the unit sphere between keys (Appendix C: normalise).
        glm::dquat q = quat_at(out);
        const double len = glm::length(q);
        q = len > 1e-12 ? q / len : glm::normalize(quat_at(v0));
        out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
    }
}

glm::dmat4 local_matrix(const RigNode& node, const NodeTrs& trs) {
    // A node with a matrix is never animated (the loader checks), §3.5.3.
    if (node.has_matrix) return node.matrix;
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), trs.translation);
    m = m * glm::mat4_cast(trs.rotation);
    return glm::scale(m, trs.scale);
}

// The matrix that maps normals under `m`: the inverse transpose, here as the
// cofactor matrix times the sign of the determinant. That is the same
// direction (only the length differs, and normals are renormalised), and it
// stays finite when a scale animates to zero.
glm::dmat3 normal_matrix(const glm::dmat3& m) {
    glm::dmat3 cof(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
    return glm::determinant(m) < 0 ? -cof : cof;
}

glm::vec3 unit_or(const glm::dvec3& n, const glm::vec3& fallback) {
    const double len = glm::length(n);
    return len > 0 && std::isfinite(len) ? glm::vec3(n / len) : fallback;
}

// The morphed mesh-space vertex v (§3.7.2.2: base + Σ weight · delta).
struct MorphedVertex {
    glm::dvec3 position, normal;
    glm::dvec3 tangent{0.0};  // xyz; zero when the part has no tangents
};

MorphedVertex morphed_vertex(const RigPart& part, const std::vector<double>& weights, size_t v) {
    MorphedVertex m{glm::dvec3(part.positions[v]), glm::dvec3(part.normals[v])};
    const bool tangents = !part.tangents.empty();
    if (tangents) m.tangent = glm::dvec3(glm::vec3(part.tangents[v]));
    for (size_t t = 0; t < part.morph_targets.size(); ++t) {
        if (weights[t] == 0) continue;
        const RigMorphTarget& target = part.morph_targets[t];
        if (!target.position_deltas.empty())
            m.position += weights[t] * glm::dvec3(target.position_deltas[v]);
        if (!target.normal_deltas.empty())
            m.normal += weights[t] * glm::dvec3(target.normal_deltas[v]);
        if (tangents && !target.tangent_deltas.empty())
            m.tangent += weights[t] * glm::dvec3(target.tangent_deltas[v]);
    }
    return m;
}

// A tangent moves with the surface: by the linear part itself, not the
// normals' inverse transpose (for any such map, the two stay
// perpendicular), and where the map mirrors, w flips so that w (n x t)
// still points up the texture.
glm::vec4 posed_tangent(const glm::dmat3& linear, const glm::dvec3& tangent,
                        const glm::vec4& rest) {
    const float flip = glm::determinant(linear) < 0 ? -1.0f : 1.0f;
    return {unit_or(linear * tangent, glm::vec3(rest)), rest.w * flip};
}

// Normals of the vertices the loader gave face normals: the area-weighted
// sum of the posed triangles around each, as the loader did at rest. When
// the pose flipped the winding, the triangles' own order points backwards.
void normals_from_faces(const RigPart& rig_part, const MeshPart& part, PosedPart& posed) {
    if (rig_part.normals_from_faces.empty()) return;
    const double side = posed.winding_flipped ? -1.0 : 1.0;
    std::vector<glm::dvec3> sum(posed.positions.size(), glm::dvec3(0.0));
    for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
        const uint32_t a = part.indices[t], b = part.indices[t + 1], c = part.indices[t + 2];
        const glm::dvec3 pa(posed.positions[a]);
        const glm::dvec3 face =
            glm::cross(glm::dvec3(posed.positions[b]) - pa, glm::dvec3(posed.positions[c]) - pa);
        for (uint32_t v : {a, b, c}) sum[v] += side * face;
    }
    for (uint32_t v : rig_part.normals_from_faces)
        posed.normals[v] = unit_or(sum[v], glm::vec3(0, 1, 0));
}

void pose_rigid(const RigPart& rig_part, const std::vector<double>& weights,
                const glm::dmat4& world, PosedPart& posed) {
    const glm::dmat3 linear(world);
    const glm::dmat3 normals = normal_matrix(linear);
    const bool tangents = !rig_part.tangents.empty();
    for (size_t v = 0; v < rig_part.positions.size(); ++v) {
        const MorphedVertex m = morphed_vertex(rig_part, weights, v);
        posed.positions[v] = glm::vec3(world * glm::dvec4(m.position, 1.0));
        posed.normals[v] = unit_or(normals * m.normal, rig_part.normals[v]);
        if (tangents) posed.tangents[v] = posed_tangent(linear, m.tangent, rig_part.tangents[v]);
    }
    posed.winding_flipped = (glm::determinant(glm::dmat3(world)) < 0) != rig_part.rest_mirrored;
}

// Vertex v's blend of its joints' matrices.
glm::dmat4 skin_matrix(const RigPart& rig_part, const std::vector<glm::dmat4>& joint_matrices,
                       size_t v) {
    const int influences = rig_part.influences;
    glm::dmat4 skin(0.0);
    for (int k = 0; k < influences; ++k) {
        const double w = rig_part.weights[v * influences + k];
        if (w != 0) skin += joint_matrices[rig_part.joints[v * influences + k]] * w;
    }
    return skin;
}

// §3.7.3.3: each vertex moves by the weighted sum of its joints' matrices
// (joint world transform × inverse bind matrix); the skinned mesh's node
// transform plays no part.
void pose_skinned(const RigPart& rig_part, const std::vector<double>& weights,
                  const std::vector<glm::dmat4>& joint_matrices, PosedPart& posed) {
    size_t mirrored_vertices = 0;
    const bool tangents = !rig_part.tangents.empty();
    for (size_t v = 0; v < rig_part.positions.size(); ++v) {
        const MorphedVertex m = morphed_vertex(rig_part, weights, v);
        const glm::dmat4 skin = skin_matrix(rig_part, joint_matrices, v);
        const glm::dmat3 linear(skin);
        if (glm::determinant(linear) < 0) ++mirrored_vertices;
        posed.positions[v] = glm::vec3(skin * glm::dvec4(m.position, 1.0));
        posed.normals[v] = unit_or(normal_matrix(linear) * m.normal, rig_part.normals[v]);
        if (tangents) posed.tangents[v] = posed_tangent(linear, m.tangent, rig_part.tangents[v]);
    }
    // A skin has no single transform; the part counts as mirrored when most
    // of its vertices are.
    const bool mirrored = 2 * mirrored_vertices > rig_part.positions.size();
    posed.winding_flipped = mirrored != rig_part.rest_mirrored;
}

void copy_rest(const MeshPart& part, PosedPart& posed) {
    posed.positions = part.positions;
    posed.normals = part.normals;
    posed.tangents = part.tangents;
    posed.winding_flipped = false;
}

// Overwrites the local transforms and morph weights that `anim` drives with
// their values at `seconds`, and marks the nodes whose transform it drives.
void apply_channels(const RigAnimation& anim, double seconds, std::vector<NodeTrs>& local,
                    std::vector<std::vector<double>>& weights, std::vector<bool>& animated) {
    // Held at both ends; NaN (no meaningful time) holds the start.
    const double time = seconds > 0 ? std::min(seconds, anim.duration) : 0.0;
    double value[4];
    for (const RigChannel& channel : anim.channels) {
        const RigSampler& sampler = anim.samplers[channel.sampler];
        NodeTrs& trs = local[channel.node];
        switch (channel.path) {
            case RigChannelPath::translation:
                sample(sampler, time, false, value);
                trs.translation = {value[0], value[1], value[2]};
                break;
            case RigChannelPath::rotation:
                sample(sampler, time, true, value);
                trs.rotation = quat_at(value);
                break;
            case RigChannelPath::scale:
                sample(sampler, time, false, value);
                trs.scale = {value[0], value[1], value[2]};
                break;
            case RigChannelPath::weights:
                sample(sampler, time, false, weights[channel.node].data());
                break;
        }
        if (channel.path != RigChannelPath::weights) animated[channel.node] = true;
    }
}

const RigAnimation& animation_at(const Mesh& mesh, int animation) {
    if (animation < 0 || animation >= animation_count(mesh))
        throw Error(ExitCode::runtime_failure,
                    mesh.source + ": no animation number " + std::to_string(animation));
    return mesh.rig->animations[animation];
}

}  // namespace

int animation_count(const Mesh& mesh) {
    return mesh.rig ? static_cast<int>(mesh.rig->animations.size()) : 0;
}

double animation_duration(const Mesh& mesh, int animation) {
    return animation_at(mesh, animation).duration;
}

int find_animation(const Mesh& mesh, const std::string& name_or_index) {
    const int count = animation_count(mesh);
    for (int i = 0; i < count; ++i)
        if (mesh.rig->animations[i].name == name_or_index) return i;
    const bool digits = !name_or_index.empty() && name_or_index.size() < 10 &&
                        std::all_of(name_or_index.begin(), name_or_index.end(),
                                    [](char c) { return c >= '0' && c <= '9'; });
    if (digits && std::stoi(name_or_index) < count) return std::stoi(name_or_index);
    std::string known;
    for (int i = 0; i < count; ++i) known += (i ? ", '" : "'") + mesh.rig->animations[i].name + "'";
    throw Error(ExitCode::invalid_input,
                mesh.source + ": no animation '" + name_or_index + "' (" +
                    (count ? "the file has " + known + ", or an index from 0 to " +
                                 std::to_string(count - 1)
                           : std::string("the file has no animations")) +
                    ")");
}

std::vector<int> find_animations(const Mesh& mesh, const std::vector<std::string>& names) {
    std::vector<int> found;
    for (const std::string& name : names) {
        if (name == "all") {
            if (animation_count(mesh) == 0)
                throw Error(ExitCode::invalid_input,
                            mesh.source + ": 'all' animations, but the file has none");
            for (int i = 0; i < animation_count(mesh); ++i) found.push_back(i);
        } else {
            found.push_back(find_animation(mesh, name));
        }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

double animations_duration(const Mesh& mesh, const std::vector<int>& animations) {
    double longest = 0;
    for (int a : animations) longest = std::max(longest, animation_duration(mesh, a));
    return longest;
}

void pose_mesh(const Mesh& mesh, int animation, double seconds, std::vector<PosedPart>& out) {
    pose_mesh(mesh, animation < 0 ? std::vector<int>{} : std::vector<int>{animation}, seconds, out);
}

namespace {

// Every node's world transform and morph weights at `seconds` into
// `animations`; `moved` marks the nodes whose transform differs from rest
// because they or an ancestor are animated.
struct NodePose {
    std::vector<glm::dmat4> world;
    std::vector<std::vector<double>> weights;
    std::vector<bool> moved;
};

NodePose pose_nodes(const Mesh& mesh, const MeshRig& rig, const std::vector<int>& animations,
                    double seconds) {
    const size_t node_count = rig.nodes.size();
    std::vector<NodeTrs> local(node_count);
    NodePose pose;
    pose.weights.resize(node_count);
    std::vector<bool> animated(node_count, false);
    for (size_t i = 0; i < node_count; ++i) {
        const RigNode& node = rig.nodes[i];
        local[i] = {node.translation, node.rotation, node.scale};
        pose.weights[i] = node.weights;
    }
    for (int animation : animations)
        apply_channels(animation_at(mesh, animation), seconds, local, pose.weights, animated);
    pose.world.resize(node_count);
    pose.moved.assign(node_count, false);
    for (int i : rig.node_order) {
        const int parent = rig.nodes[i].parent;
        const glm::dmat4 l = local_matrix(rig.nodes[i], local[i]);
        pose.world[i] = parent >= 0 ? pose.world[parent] * l : l;
        pose.moved[i] = animated[i] || (parent >= 0 && pose.moved[parent]);
    }
    return pose;
}

// Each joint's world transform times its inverse bind matrix.
std::vector<glm::dmat4> skin_joint_matrices(const RigSkin& skin, const NodePose& pose) {
    std::vector<glm::dmat4> out;
    for (size_t j = 0; j < skin.joints.size(); ++j)
        out.push_back(pose.world[skin.joints[j]] * skin.inverse_bind[j]);
    return out;
}

// `from_rig`: every skinned or morphed part is computed from the rig, even
// where its weights are the defaults the loaded parts were baked with.
void pose_parts(const Mesh& mesh, const std::vector<int>& animations, double seconds, bool from_rig,
                std::vector<PosedPart>& out) {
    out.resize(mesh.parts.size());
    const MeshRig* rig = mesh.rig.get();
    if (!rig) {
        for (size_t p = 0; p < mesh.parts.size(); ++p) copy_rest(mesh.parts[p], out[p]);
        return;
    }
    const NodePose pose = pose_nodes(mesh, *rig, animations, seconds);
    std::vector<std::vector<glm::dmat4>> joint_matrices(rig->skins.size());
    for (size_t s = 0; s < rig->skins.size(); ++s)
        joint_matrices[s] = skin_joint_matrices(rig->skins[s], pose);
    for (size_t p = 0; p < mesh.parts.size(); ++p) {
        const RigPart& rig_part = rig->parts[p];
        const std::vector<double>& part_weights = pose.weights[rig_part.node];
        // The loaded parts hold the default weights' shape.
        const bool morphed = !rig_part.morph_targets.empty() &&
                             (from_rig || part_weights != rig->nodes[rig_part.node].weights);
        PosedPart& posed = out[p];
        if (rig_part.skin < 0 && !pose.moved[rig_part.node] && !morphed) {
            copy_rest(mesh.parts[p], posed);
            continue;
        }
        posed.positions.resize(rig_part.positions.size());
        posed.normals.resize(rig_part.positions.size());
        posed.tangents.resize(rig_part.tangents.size());
        if (rig_part.skin >= 0)
            pose_skinned(rig_part, part_weights, joint_matrices[rig_part.skin], posed);
        else
            pose_rigid(rig_part, part_weights, pose.world[rig_part.node] * rig_part.instance,
                       posed);
        normals_from_faces(rig_part, mesh.parts[p], posed);
    }
}

}  // namespace

void pose_mesh(const Mesh& mesh, const std::vector<int>& animations, double seconds,
               std::vector<PosedPart>& out) {
    pose_parts(mesh, animations, seconds, false, out);
}

void pose_rest_from_rig(const Mesh& mesh, std::vector<PosedPart>& out) {
    pose_parts(mesh, {}, 0.0, true, out);
}

std::vector<glm::vec4> rest_tangents_in_mesh_space(const Mesh& mesh, size_t part,
                                                   const std::vector<glm::vec4>& baked) {
    const MeshRig& rig = *mesh.rig;
    const RigPart& rig_part = rig.parts[part];
    const NodePose pose = pose_nodes(mesh, rig, {}, 0.0);
    std::vector<glm::dmat4> joints;
    if (rig_part.skin >= 0) joints = skin_joint_matrices(rig.skins[rig_part.skin], pose);
    const glm::dmat3 rigid(pose.world[rig_part.node] * rig_part.instance);
    std::vector<glm::vec4> out(baked.size());
    for (size_t v = 0; v < baked.size(); ++v) {
        const glm::dmat3 linear =
            rig_part.skin >= 0 ? glm::dmat3(skin_matrix(rig_part, joints, v)) : rigid;
        const double det = glm::determinant(linear);
        if (!(std::fabs(det) > 0) || !std::isfinite(det)) {
            out[v] = baked[v];
            continue;
        }
        const glm::vec3 rest(baked[v]);
        out[v] = {unit_or(glm::inverse(linear) * glm::dvec3(rest), rest),
                  det < 0 ? -baked[v].w : baked[v].w};
    }
    return out;
}

glm::dmat4 node_world_matrix(const MeshRig& rig, const std::vector<int>& animations, double seconds,
                             int node) {
    const size_t node_count = rig.nodes.size();
    std::vector<NodeTrs> local(node_count);
    std::vector<std::vector<double>> weights(node_count);
    std::vector<bool> animated(node_count, false);
    for (size_t i = 0; i < node_count; ++i) {
        local[i] = {rig.nodes[i].translation, rig.nodes[i].rotation, rig.nodes[i].scale};
        weights[i] = rig.nodes[i].weights;
    }
    for (int a : animations)
        apply_channels(rig.animations.at(static_cast<size_t>(a)), seconds, local, weights,
                       animated);
    // The chain from the node up to its root, applied root first.
    glm::dmat4 world(1.0);
    for (int n = node; n >= 0; n = rig.nodes[static_cast<size_t>(n)].parent)
        world =
            local_matrix(rig.nodes[static_cast<size_t>(n)], local[static_cast<size_t>(n)]) * world;
    return world;
}

std::vector<int> animations_moving(const MeshRig& rig, int node) {
    std::vector<bool> chain(rig.nodes.size(), false);
    for (int n = node; n >= 0; n = rig.nodes[static_cast<size_t>(n)].parent)
        chain[static_cast<size_t>(n)] = true;
    std::vector<int> out;
    for (size_t a = 0; a < rig.animations.size(); ++a)
        for (const RigChannel& c : rig.animations[a].channels)
            if (c.path != RigChannelPath::weights && chain[static_cast<size_t>(c.node)]) {
                out.push_back(static_cast<int>(a));
                break;
            }
    return out;
}

}  // namespace facet
