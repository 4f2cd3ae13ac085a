#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

// Writes the bytes to a temporary file beside `path`, flushes it, then
// renames it over `path`, so readers see the old file or the new one, never
// half of one. Throws facet::Error (io_failure) naming the path.
void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes);
void write_file_atomically(const std::string& path, const std::string& text);

// Creates the folder and its parents; throws io_failure if that fails.
void make_directories(const std::string& path);

}  // namespace facet
