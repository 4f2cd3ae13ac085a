#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

// This machine's name, with '/' and '.' made '_' so that it can sit inside
// a file name between dots (temporaries, journals).
std::string host_name();

// Writes the bytes to a temporary file beside `path` (".NAME.facet-tmp.HOST.PID"),
// syncs it to disk, renames it over `path` and syncs the folder, so readers
// see the old file or the new one, never half of one, even after a power
// loss. Throws facet::Error (io_failure) naming the path.
void write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes);
void write_file_atomically(const std::string& path, const std::string& text);

// Creates the folder and its parents; throws io_failure if that fails.
void make_directories(const std::string& path);

// Removes the temporary files an earlier run on this host left in `folder`
// when it was killed mid-write (their process is gone); returns how many.
// Another live process's temporaries, and other hosts', are left alone.
size_t remove_stale_temporaries(const std::string& folder);

}  // namespace facet
