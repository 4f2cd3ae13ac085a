#pragma once
// A check of a PLY file's structure before libassimp reads it: assimp
// 5.2.5's PLY reader aborts, crashes or loops on files whose data ends
// before their header says it does. The header is parsed and every element
// walked (binary: byte by byte through the lists; ASCII: token by token),
// without keeping anything.
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

// Throws facet::Error (invalid_input) "PATH: PLY ...: what is wrong" unless
// `bytes` is a complete PLY file: a header that ends, known formats and
// types, and as much data as the header declares.
void check_ply(const std::vector<uint8_t>& bytes, const std::string& path);

}  // namespace facet
