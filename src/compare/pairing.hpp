#pragma once
// Which file of REF goes with which of NEW: through the two manifests by
// (camera, pass, frame, format), or two lone image files.
#include <string>
#include <vector>

#include "compare/compare_run.hpp"

namespace facet {

struct FilePair {
    FileKey key;
    ImageKind kind = ImageKind::color;
    std::string ref_path, new_path;      // "" when that run has no such file
    std::string ref_sha256, new_sha256;  // as the manifests record them ("" for lone files)
};

// Pairs in key order. Throws Error: io_failure when a folder has no
// readable manifest or a path is neither a folder nor a file;
// invalid_input when one is a folder and the other a file.
std::vector<FilePair> pair_files(const std::string& ref, const std::string& candidate);

}  // namespace facet
