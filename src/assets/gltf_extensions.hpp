#pragma once
// Internal to the glTF loader: which glTF extensions facet reads, the check
// of a file's extension lists against them, and KHR_texture_transform.
// Only assets/ includes this header, because it brings in tinygltf.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/vec2.hpp>

#include "assets/texture.hpp"
#include "core/diagnostics.hpp"

namespace facet::gltf_detail {

// A whole file with its JSON rewritten: a .gltf's text, or a .glb rebuilt
// around its rewritten JSON chunk (other chunks kept as they are). For
// compression extensions whose files tinygltf would refuse as they are.
std::vector<uint8_t> with_json_rewritten(
    const std::vector<uint8_t>& file,
    const std::function<std::string(const std::string&)>& rewrite);

struct ExtensionLists {
    std::vector<std::string> required, used;
    // In either list.
    bool lists(const std::string& extension) const;
};

// The file's extensionsRequired and extensionsUsed, read from its JSON
// (the JSON chunk of a .glb) before tinygltf parses the rest. A file that
// needs compressed geometry can fail tinygltf's own checks of its buffers
// ("Invalid byteLength") before the extension lists are looked at; reading
// them first lets the error name the extension. Empty lists when the JSON
// cannot be read: tinygltf then reports why. The same read checks the types
// of the fields facet draws from (check_field_types, gltf_field_types.hpp).
ExtensionLists read_extension_lists(std::span<const uint8_t> bytes, const std::string& path);

struct ExtensionCheck {
    std::vector<std::string> ignored;  // listed, but not read by facet
    Warnings warnings;
};

// An extension facet does not support is an error (invalid_input, naming
// it and what it does) when the file requires it, thrown, or appended to
// `refusals` when given (`facet info`: the file is read on, and the error
// reported as render reports it); and a warning naming it and what is lost
// when the file only uses it. KHR_texture_basisu is left to
// check_basisu_fallbacks (gltf_materials.hpp).
ExtensionCheck check_extensions(const ExtensionLists& lists, const std::string& path,
                                std::vector<Error>* refusals);

// How a textureInfo is read: its texture coordinate set, and its
// KHR_texture_transform.
struct UvMapping {
    int tex_coord = 0;
    UvTransform transform;
};

// The textureInfo's transform (identity with its texCoord when it has
// none). Throws invalid_input for values that are not finite.
UvMapping texture_mapping(const tinygltf::TextureInfo& info, const std::string& path,
                          const std::string& what);

}  // namespace facet::gltf_detail
