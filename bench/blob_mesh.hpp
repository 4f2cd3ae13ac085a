#pragma once
// The benchmark's generated meshes (blob_mesh.cpp).
#include <cstdint>
#include <string>

namespace facet_bench {

// An icosphere of 20 * 4^levels triangles, radius about 1, displaced by a
// smooth function that `seed` picks, as OBJ with a spherical UV map.
void write_blob_obj(const std::string& path, int levels, uint32_t seed);

// A size x size PNG texture for the textured case.
void write_blob_texture(const std::string& path, int size);

}  // namespace facet_bench
