#pragma once
// Internal to the glTF loader: a mesh primitive's vertex attributes read
// once in mesh space (glTF 2.0 §3.7.2), then placed as a baked part for
// each node and instance that shows it. Only assets/ includes this header,
// because it brings in tinygltf.
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/mat4x4.hpp>

#include "assets/mesh.hpp"
#include "core/diagnostics.hpp"

namespace facet::gltf_detail {

// One triangle primitive as the file stores it, before any transform.
struct MeshSpacePrimitive {
    std::string what;  // "mesh 'name' primitive N", for messages
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // the file's, unnormalised; empty when it has none
    // TANGENT: xyz unit (or zero where the file's had no length), w exactly
    // +1 or -1; empty when the file has none, or has no normals (§3.7.2.1:
    // its tangents are then ignored).
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec2> uvs, uvs1;         // TEXCOORD_0 and TEXCOORD_1, or empty
    std::vector<glm::vec3> colors;            // COLOR_0's RGB, or empty
    std::vector<uint32_t> indices;            // a triangle list
    uint32_t material = 0;                    // the file's index, or the default material
    std::vector<uint32_t> variant_materials;  // as MeshPart's (KHR_materials_variants)
};

// The primitive's attributes, checked; nullopt (with a warning) for points,
// lines and primitives without positions or triangles.
std::optional<MeshSpacePrimitive> read_primitive(const tinygltf::Model& model,
                                                 const tinygltf::Primitive& primitive,
                                                 const std::string& path, const std::string& what,
                                                 uint32_t default_material, Warnings& warnings);

// The primitive placed by `world` (node and instance transforms): positions,
// normals and tangents transformed (a tangent by the transform itself, its
// w flipped where the transform mirrors), triangles reversed where the transform mirrors,
// flat normals where the file has none and face normals where its normals
// have no length (each with a warning). `source_vertex`, when given,
// receives for each vertex of the part the primitive's vertex it came from.
// Normals are computed on the pool's threads when there is one.
MeshPart place_primitive(const MeshSpacePrimitive& primitive, const glm::mat4& world,
                         const std::string& path, Warnings& warnings,
                         std::vector<uint32_t>* source_vertex, ThreadPool* pool);

}  // namespace facet::gltf_detail
