#pragma once
// What each fuzz harness does with one input: write it where a user's file
// would be and load it as facet does. A facet::Error is the expected answer
// to bad input; anything else (another exception, a sanitizer report, a
// hang or a runaway allocation) is a finding. The libFuzzer entry points
// (fuzz_main.cpp, scripts/fuzz.sh) and the regression replay in the normal
// suite (tests/test_fuzz_inputs.cpp) both call these.
#include <cstddef>
#include <cstdint>
#include <string>

namespace facet::fuzz {

// The harnesses by name: "scene" (scene and style loader), "obj", "gltf",
// "texture", "environment" (a .hdr or .exr environment map, told by its
// bytes), "ply", "assimp" (STL, FBX, Collada and 3DS through assimp: the
// input's first byte chooses the file's name), "manifest" (manifest and run
// journal reader: render, compare,
// merge and video read manifests with it), "override" (the -D parser,
// applied to a small scene). Returns false for an unknown name.
bool run_target(const std::string& target, const uint8_t* data, size_t size);

void fuzz_scene(const uint8_t* data, size_t size);
void fuzz_obj(const uint8_t* data, size_t size);
void fuzz_gltf(const uint8_t* data, size_t size);
void fuzz_texture(const uint8_t* data, size_t size);
void fuzz_environment(const uint8_t* data, size_t size);
void fuzz_ply(const uint8_t* data, size_t size);
void fuzz_assimp(const uint8_t* data, size_t size);
void fuzz_manifest(const uint8_t* data, size_t size);
void fuzz_override(const uint8_t* data, size_t size);

}  // namespace facet::fuzz
