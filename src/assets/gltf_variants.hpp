#pragma once
// Internal to the glTF loader: KHR_materials_variants, a product's
// colourways. The file lists the variants' names at its root; each
// primitive maps materials to some of them. Only assets/ includes this
// header, because it brings in tinygltf.
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/diagnostics.hpp"

namespace facet::gltf_detail {

// The names of the file's variants (extensions.KHR_materials_variants.
// variants), in its order; none without the extension. A name given twice
// is a warning: a variant is chosen by its name, so the second is never
// drawn. The JSON types were checked before (gltf_field_types.cpp).
std::vector<std::string> read_variant_names(const tinygltf::Model& model, const std::string& path,
                                            Warnings* warnings = nullptr);

// The primitive's mappings as MeshPart::variant_materials: empty when it
// has none, else one material per variant of the file, `material` (the
// primitive's own) where no mapping names the variant. A mapping naming a
// material or a variant the file does not have, or a variant a second
// time, is an error (invalid_input) naming the file, the primitive
// (`what`) and the mapping's key.
std::vector<uint32_t> read_variant_materials(const tinygltf::Model& model,
                                             const tinygltf::Primitive& primitive,
                                             uint32_t material, const std::string& path,
                                             const std::string& what);

}  // namespace facet::gltf_detail
