#pragma once
// Internal to the glTF loader: reading the data that poses a mesh (nodes,
// skins, morph targets, animations) into a MeshRig. gltf_loader.cpp bakes
// the rest pose and calls these alongside.
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "assets/mesh_rig.hpp"
#include "core/diagnostics.hpp"

namespace facet::gltf_detail {

// Whether the file has animations, skins or morph targets: only then is a
// MeshRig kept.
bool has_rig_data(const tinygltf::Model& model);

// The node tree, skins and animations, all checked. Channels the loader
// cannot use (no target node, or a path added by an extension) are left out
// with a warning.
void read_rig_nodes_and_animations(const tinygltf::Model& model, const std::string& path,
                                   MeshRig& rig, Warnings& warnings);

// Fills the skin and morph data of `part`, whose node, skin and mesh-space
// positions are already set, from `primitive`, in the file's vertex order.
// `rig` must already hold the nodes and skins.
void read_part_skin_and_morph(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                              const MeshRig& rig, const std::string& path, const std::string& what,
                              RigPart& part);

}  // namespace facet::gltf_detail
