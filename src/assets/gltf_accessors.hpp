#pragma once
// Internal to the glTF loader (gltf_*.cpp): bounds-checked reading of
// accessors, and the one way every glTF problem is reported. Only assets/
// includes this header, because it brings in tinygltf.
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace facet::gltf_detail {

// Throws facet::Error (invalid_input) as "<path>: <what>".
[[noreturn]] void bad(const std::string& path, const std::string& what);

// The accessor `index`, or an error naming `what` when it does not exist.
const tinygltf::Accessor& accessor_at(const tinygltf::Model& model, int index,
                                      const std::string& path, const std::string& what);

// Checks that the accessor's count fits its data (or the limit for an
// accessor without data) without reading or allocating anything, so that a
// count can be trusted in memory estimates.
void check_accessor_data(const tinygltf::Model& model, int index, const std::string& path,
                         const std::string& what);

// Reads an accessor as floats, `components` per element, applying sparse
// substitution and normalisation; every value is checked to be finite.
std::vector<float> read_floats(const tinygltf::Model& model, int index, int components,
                               const std::string& path, const std::string& what);

// Reads a SCALAR accessor of unsigned integers (primitive indices).
std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index,
                                   const std::string& path);

}  // namespace facet::gltf_detail
