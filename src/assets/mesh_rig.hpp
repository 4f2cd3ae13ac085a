#pragma once
// What a glTF file says about moving its meshes, kept as plain data beside
// the baked rest pose: the node tree, skins, morph targets and animations
// (glTF 2.0 §3.5 nodes, §3.7.3 skins, §3.7.2.2 morph targets, §3.11
// animations). assets/gltf_pose.hpp turns it into posed vertices.
//
// Node, skin and animation indices are the file's own, so messages and
// tools can name them as the file does. Every index and count here was
// checked by the loader: code that reads a MeshRig need not check again.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

struct RigNode {
    std::string name;  // the file's, or "node<index>" when it has none
    int parent = -1;   // -1 for a root
    // The local transform at rest: the file's matrix when it gave one
    // (such a node cannot be animated, glTF §3.11.1), else T·R·S of the
    // fields below. Double, like the file's JSON numbers.
    bool has_matrix = false;
    glm::dmat4 matrix = glm::dmat4(1.0);
    glm::dvec3 translation = glm::dvec3(0.0);
    glm::dquat rotation = glm::dquat(1.0, 0.0, 0.0, 0.0);  // unit length
    glm::dvec3 scale = glm::dvec3(1.0);
    // Default morph target weights of the mesh this node shows: node.weights,
    // else mesh.weights, else zeros (§3.7.2.2). Empty when it has no targets.
    std::vector<double> weights;
};

struct RigSkin {
    std::vector<int> joints;               // node indices
    std::vector<glm::dmat4> inverse_bind;  // one per joint; identity when the file has none
};

// One morph target of one part: per-vertex displacements, each list either
// empty (the target does not move that attribute) or one per vertex.
struct RigMorphTarget {
    std::vector<glm::vec3> position_deltas;
    std::vector<glm::vec3> normal_deltas;
    std::vector<glm::vec3> tangent_deltas;  // of the tangents' xyz; w does not morph
};

// The un-baked source of Mesh::parts[i], vertex for vertex in the same order.
struct RigPart {
    int node = -1;  // the node that instantiated the mesh
    // One copy of EXT_mesh_gpu_instancing: its transform, applied between
    // the mesh and the node (identity without instancing).
    glm::dmat4 instance = glm::dmat4(1.0);
    int skin = -1;  // that node's skin, or -1
    // The baked rest transform had a negative determinant, so the loader
    // reversed the part's triangles; posing compares against this.
    bool rest_mirrored = false;
    std::vector<glm::vec3> positions;  // mesh space (before any node transform)
    std::vector<glm::vec3> normals;    // mesh space, unit length; see below
    // Vertices whose normal the loader derived from the faces around them
    // (the file gave none, or a zero one): posing recomputes these from
    // the posed triangles instead of transforming `normals`.
    std::vector<uint32_t> normals_from_faces;
    // Mesh space, as MeshPart::tangents (xyz unit, w = +1 or -1), or empty
    // when the baked part has none. Posed as the normals are, but by the
    // transform itself rather than its inverse transpose.
    std::vector<glm::vec4> tangents;
    // Skinning: `influences` joints per vertex (four per JOINTS_n set);
    // joints index RigSkin::joints, and each vertex's weights sum to 1.
    int influences = 0;
    std::vector<uint16_t> joints;
    std::vector<float> weights;
    std::vector<RigMorphTarget> morph_targets;  // as many as the node's weights
};

enum class RigChannelPath { translation, rotation, scale, weights };
enum class RigInterpolation { linear, step, cubic_spline };

// glTF §3.11.2: keyframe times (strictly increasing, ≥ 0) and values.
// `components` values per key: 3 for translation and scale, 4 for rotation
// (x, y, z, w, unit length except cubic-spline tangents), the morph target
// count for weights. A cubic spline stores three elements per key:
// in-tangent, value, out-tangent.
struct RigSampler {
    std::vector<double> times;
    std::vector<double> values;
    int components = 0;
    RigInterpolation interpolation = RigInterpolation::linear;
};

struct RigChannel {
    int node = 0;
    RigChannelPath path = RigChannelPath::translation;
    int sampler = 0;  // index into RigAnimation::samplers
};

struct RigAnimation {
    std::string name;  // the file's name, or "animation<index>" when it has none
    std::vector<RigSampler> samplers;
    std::vector<RigChannel> channels;  // at most one per (node, path)
    double duration = 0;               // the last keyframe time of the samplers the channels use
};

struct MeshRig {
    std::vector<RigNode> nodes;   // every node of the file, in file order
    std::vector<int> node_order;  // every node, parents before children
    std::vector<RigSkin> skins;   // in file order
    std::vector<RigPart> parts;   // one per Mesh::parts entry, in the same order
    std::vector<RigAnimation> animations;
};

// Rebuilds the per-vertex lists of `part` after the baked part's vertices
// were split or reordered: new vertex i copies old vertex source_vertex[i].
void reorder_rig_part_vertices(RigPart& part, const std::vector<uint32_t>& source_vertex);

}  // namespace facet
