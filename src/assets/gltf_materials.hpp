#pragma once
// Internal to the glTF loader: a file's materials (glTF 2.0 §3.9) and the
// textures they read, each texture decoded once, with its own sampler
// (§3.8.4), coordinate set and KHR_texture_transform. Only assets/
// includes this header, because it brings in tinygltf.
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "assets/mesh.hpp"
#include "core/diagnostics.hpp"

namespace facet::gltf_detail {

// Images that tinygltf could not read from their URI, with the reason:
// those textures are lost (a warning), never the file.
using UnreadImages = std::map<std::string, std::string>;

// Each material of the file, in file order. Only the images a material
// reads are decoded (by their bytes: PNG, JPEG, WebP, AVIF), charged to
// `budget`. A texture that is missing or cannot be decoded is a warning
// naming the file, the material and the map, and the material is drawn
// without it; a texture whose only image is KTX2 likewise, unless the
// file requires KHR_texture_basisu (`basisu_required`: a render refuses
// the file, check_basisu_fallbacks). The metallic-roughness, normal and
// occlusion maps are read as data (Texture::as_data); which style draws
// them is the renderer's business.
std::vector<Material> read_materials(const tinygltf::Model& model, const std::string& path,
                                     const UnreadImages& unread, TextureBudget* budget,
                                     bool basisu_required, Warnings& warnings);

// KHR_texture_basisu when the file requires it: every texture must keep a
// PNG/JPEG `source` as a fallback (then a warning), else an error that
// says there is none: thrown, or appended to `refusals` when given (as
// check_extensions does).
void check_basisu_fallbacks(const tinygltf::Model& model, const std::string& path, bool required,
                            Warnings& warnings, std::vector<Error>* refusals);

}  // namespace facet::gltf_detail
