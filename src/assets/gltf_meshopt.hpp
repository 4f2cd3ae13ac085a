#pragma once
// Internal to the glTF loader: EXT_meshopt_compression, the compression of
// gltfpack -cc and of many web pipelines, decoded with libmeshoptimizer.
// Only assets/ includes this header, because it brings in tinygltf.
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace facet::gltf_detail {

// A file's JSON with each EXT_meshopt_compression fallback buffer (one
// that has a length but no data: the data is in the compressed views) made
// a tiny data URI, so that tinygltf accepts it. The views that point into
// it are decoded afterwards by decode_meshopt_views. `json` is the .gltf
// text or the .glb's JSON chunk (gltf_extensions.hpp, with_json_rewritten).
std::string without_fallback_buffers(const std::string& json);

// Decodes every bufferView that carries EXT_meshopt_compression into a
// buffer of its own and points the view there, so the accessors read the
// plain data. Throws invalid_input naming the view for a stream that does
// not decode or does not fit its buffer.
void decode_meshopt_views(tinygltf::Model& model, const std::string& path);

}  // namespace facet::gltf_detail
