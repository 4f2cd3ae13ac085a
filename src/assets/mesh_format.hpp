#pragma once
// Which mesh format a file holds, told by its bytes as well as by its name:
// a model downloaded as `model.bin`, saved without an extension or named
// for the wrong format is still read by the loader its bytes call for
// (load_mesh), and `facet render FILE` tells a mesh from a scene.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace facet {

enum class MeshFormat { obj, gltf, glb, stl, ply, fbx, collada, max3ds };

// "glTF binary (.glb)", "STL", ...: for messages.
std::string mesh_format_name(MeshFormat format);

// The formats facet reads, for messages: "glTF (.gltf, .glb), OBJ (.obj), ...".
std::string mesh_formats_read();
// The format's usual extension, without the dot ("stl").
std::string_view mesh_format_extension(MeshFormat format);

// The format a file's first bytes show, if they show one. `head` is the
// start of the file (up to kMeshSniffBytes), `file_size` its whole size
// (a binary STL is known by its size). Text formats are told by their
// first statements, binary ones by their magic numbers.
inline constexpr size_t kMeshSniffBytes = 64 * 1024;
std::optional<MeshFormat> mesh_format_of_bytes(std::span<const uint8_t> head, uint64_t file_size);

// The format a file name's extension names (any letter case), if any.
std::optional<MeshFormat> mesh_format_of_name(const std::string& path);

// The format of the file at `path`: by its bytes, else by its name; none
// when neither tells (or the file cannot be read: the loader says why).
std::optional<MeshFormat> recognise_mesh_file(const std::string& path);

}  // namespace facet
