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

// An input file read by ranges (pread), for a file too big to copy whole:
// a fresh buffer the size of a 90 MB file costs more in page faults than
// reading it does. Opened after require_input_file; its size is the one it
// had when opened (checked as a regular file again, on the open file). No
// mmap: a file cut short while mapped would kill the process (SIGBUS);
// here a range the file no longer holds is an io_failure instead.
class InputFileReader {
  public:
    InputFileReader(const std::string& path, const std::string& what);
    ~InputFileReader();
    InputFileReader(const InputFileReader&) = delete;
    InputFileReader& operator=(const InputFileReader&) = delete;

    uint64_t size() const { return size_; }
    const std::string& path() const { return path_; }
    // Bytes [offset, offset + count) into `out`; throws facet::Error
    // (io_failure) when the file no longer has them.
    void read_at(uint64_t offset, char* out, size_t count) const;

  private:
    std::string path_, what_;
    int fd_ = -1;
    uint64_t size_ = 0;
};

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
