#pragma once
// Internal to the glTF loader: the JSON types of the fields facet draws
// from, checked before tinygltf reads the file. tinygltf skips an optional
// field of the wrong type without a word, so a material whose
// pbrMetallicRoughness is a list, or a texture index of -1, would lose its
// texture silently.
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace facet::gltf_detail {

// Throws invalid_input naming the file and the field ("materials[0].
// pbrMetallicRoughness must be an object") when a field facet reads has
// another JSON type than glTF 2.0's schema gives it, or an index is
// negative. Fields facet does not read (names, extras) are not checked.
void check_field_types(const nlohmann::json& doc, const std::string& path);

}  // namespace facet::gltf_detail
