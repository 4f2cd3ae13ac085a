#pragma once
// Files facet reads: what stands in the way of reading one, said plainly,
// and the policy for paths that come from inside assets (an OBJ's mtllib
// and map_Kd, a glTF's buffer and image URIs), which nobody on the team
// may have looked at.
#include <cstdint>
#include <string>
#include <vector>

namespace facet {

// Why `path` cannot be read as an input file: "" when it can, else a
// reason such as "no such file", "is a directory", "is not a regular file
// (a FIFO)", "symbolic link loop", "permission denied", or "is 3.2 GB,
// over the limit of 1 GB" when `max_bytes` > 0. Follows symbolic links.
std::string input_file_problem(const std::string& path, uint64_t max_bytes = 0);

// Throws facet::Error (invalid_input) "PATH: cannot read WHAT: REASON"
// when input_file_problem finds one.
void require_input_file(const std::string& path, const std::string& what, uint64_t max_bytes = 0);

// The whole file, after require_input_file; read errors are io_failure.
std::vector<uint8_t> read_input_file(const std::string& path, const std::string& what,
                                     uint64_t max_bytes = 0);

// "1.5 GB", "320 MB", "12 KB", "17 bytes".
std::string describe_bytes(uint64_t bytes);

// How paths named inside assets are resolved and checked.
struct AssetPathPolicy {
    // Off: such a path must resolve (symbolic links followed) inside the
    // folder of the file that names it, or below it.
    bool allow_outside = false;
    uint64_t max_file_bytes = uint64_t(2) << 30;  // per referenced file
};

// The file a path inside `asset` refers to: `reference` resolved against
// the asset's folder, checked against the policy and as an input file.
// Throws facet::Error (invalid_input) "ASSET: WHERE: 'REFERENCE' REASON",
// where WHERE names the key or line that holds the path.
std::string resolve_asset_reference(const std::string& asset, const std::string& where,
                                    const std::string& reference, const AssetPathPolicy& policy);

}  // namespace facet
