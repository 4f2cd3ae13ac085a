#pragma once
// Internal to the glTF loader: KHR_draco_mesh_compression, decoded with
// Debian's libdraco. Only assets/ includes this header, because it brings
// in tinygltf.
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace facet::gltf_detail {

// A file's JSON with a placeholder bufferView given to every accessor that
// has none and is not sparse: a Draco-compressed primitive's accessors hold
// no data of their own, and tinygltf refuses accessors without a view. The
// placeholder is the last view; `placeholder_view` receives its index, or
// -1 when nothing was changed. decode_draco_primitives takes the
// placeholder out again.
std::string with_placeholder_views(const std::string& json, int& placeholder_view);

// Decodes every primitive that carries KHR_draco_mesh_compression: its
// compressed bufferView becomes a mesh, and each attribute the extension
// names (and the indices) gets a new accessor over a new buffer of plain
// data, in the component type the file's accessor declares. The primitive
// then points at the new accessors, so everything after reads plain glTF.
// Throws invalid_input naming the mesh and primitive for a stream that does
// not decode or disagrees with the file's accessors.
// Accessors still on the placeholder view afterwards get no view again
// (zeros, glTF §3.6.2.3).
void decode_draco_primitives(tinygltf::Model& model, const std::string& path, int placeholder_view);

}  // namespace facet::gltf_detail
