#pragma once
// `facet merge OUTDIR`: the partial manifests a farm job's tasks wrote,
// checked and combined into manifest.json (docs/farm.md, "Merge").
#include <string>
#include <vector>

namespace facet {

struct MergeRequest {
    std::string folder;  // the manifests' folder
    bool keep_parts = false;
    std::vector<std::string> command_line;  // of the merge, for the merged manifest
};

struct MergeReport {
    std::vector<std::string> parts;  // partial manifests read, by file name
    // Every reason the job is not whole: frames missing or listed twice,
    // files missing or not as recorded, parts of other settings or jobs.
    // When there is any, nothing is written.
    std::vector<std::string> problems;
    std::vector<std::string> warnings;  // e.g. parts rendered by different facet builds
    size_t frames = 0, files = 0;       // in the merged (or checked) manifest
    std::string manifest_path;          // written, or checked when there were no parts
    bool checked_only = false;          // no partial manifests: manifest.json was checked
};

// Throws Error(invalid_input) when the folder holds neither partial
// manifests nor manifest.json, and io_failure when it cannot be read.
MergeReport merge_partial_manifests(const MergeRequest& request);

}  // namespace facet
