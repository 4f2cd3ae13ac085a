#pragma once
// glTF animation, skinning and morph targets applied to a loaded Mesh: a pure
// function of the mesh, the animation and the time (glTF 2.0 §3.7.2.2,
// §3.7.3, §3.11 and Appendix C). Looping and the choice of time are the
// caller's.
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/mesh.hpp"

namespace facet {

// One part of the mesh, posed: same model space, vertex order and count as
// Mesh::parts[i], whose indices and UVs still apply.
struct PosedPart {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // unit length
    // As MeshPart::tangents (xyz unit, w = +1 or -1, flipped where the pose
    // mirrors the part), or empty when the part has none.
    std::vector<glm::vec4> tangents;
    // The pose mirrors the part where its rest pose did not, or the other
    // way round (a negative scale was animated), so the part's triangles now
    // wind clockwise seen from their front: swap two corners of each.
    bool winding_flipped = false;
};

// The animations a mesh holds (0 when it has no rig).
int animation_count(const Mesh& mesh);

// Seconds from 0 to the animation's last keyframe.
double animation_duration(const Mesh& mesh, int animation);

// The animation named `name_or_index`, or failing that the animation with
// that decimal index. Throws facet::Error (invalid_input) naming the mesh
// and listing its animations when there is none.
int find_animation(const Mesh& mesh, const std::string& name_or_index);

// The animations `names` pick, in the file's order, each once: names or
// indices as find_animation takes them, or "all" for every one. Throws
// facet::Error (invalid_input) as find_animation does, and for "all" in a
// file without animations.
std::vector<int> find_animations(const Mesh& mesh, const std::vector<std::string>& names);

// The longest of the animations' durations: they play together, and a
// shorter one holds its last pose until the longest ends.
double animations_duration(const Mesh& mesh, const std::vector<int>& animations);

// Poses every part of `mesh` at `seconds` into each of `animations`, each
// clamped to its own [0, duration]: before the first and after the last
// keyframe the pose holds. Where two of them drive the same node property,
// the later in the file wins. No animations poses the nodes' rest
// transforms, skins and default morph weights. `out` gets one entry per part; its
// vectors are reused from call to call.
//
// A part that nothing moves (its node and the node's ancestors are not
// animated, it has no skin and its morph weights are its node's defaults)
// comes out bit-identical to Mesh::parts. Otherwise the pose is computed in double:
// a rigid part's node transform, or for a skinned part only its joints
// (the node's own transform is ignored, §3.7.3.3), after the morph targets.
void pose_mesh(const Mesh& mesh, const std::vector<int>& animations, double seconds,
               std::vector<PosedPart>& out);
// One animation, or -1 for none.
void pose_mesh(const Mesh& mesh, int animation, double seconds, std::vector<PosedPart>& out);

// The rest pose (no animation) computed from the rig for every skinned or
// morphed part: what the glTF loader bakes into Mesh::parts.
void pose_rest_from_rig(const Mesh& mesh, std::vector<PosedPart>& out);

// Tangents of part `part` as baked into Mesh::parts (its rest pose) taken
// back to the rig's mesh space, for RigPart::tangents: the inverse of the
// rest transform (a skinned vertex's own blend of joints), so that posing
// at rest gives `baked` again. Where that transform is singular the baked
// tangent is kept.
std::vector<glm::vec4> rest_tangents_in_mesh_space(const Mesh& mesh, size_t part,
                                                   const std::vector<glm::vec4>& baked);

// The world matrix of one node of `rig` at `seconds` into `animations`
// (indices into rig.animations, played together, held at their ends).
glm::dmat4 node_world_matrix(const MeshRig& rig, const std::vector<int>& animations, double seconds,
                             int node);

// The animations of `rig` that move `node` or one of its ancestors.
std::vector<int> animations_moving(const MeshRig& rig, int node);

}  // namespace facet
