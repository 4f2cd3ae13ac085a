#pragma once
// `--update-reference failed|missing|all`: copies NEW's files into the
// reference folder and updates its manifest, rewriting only what the mode
// names (docs/regression.md, "Updating references").
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/compare_run.hpp"
#include "core/enum_names.hpp"

namespace facet {

enum class UpdateMode {
    failed,   // files that failed or whose size changed
    missing,  // files NEW has and the reference lacks
    all,      // every file of NEW (reference files NEW lacks are kept)
};
inline constexpr EnumName<UpdateMode> kUpdateModes[] = {
    {UpdateMode::failed, "failed"}, {UpdateMode::missing, "missing"}, {UpdateMode::all, "all"}};

struct UpdateResult {
    std::vector<std::string> written;  // labels of the files written
    int unresolved_failures = 0;       // failing files the mode left alone
};

// Gives the reference folder a manifest with NEW's header and no files
// when it has none, so a first run can fill it. Creates the folder.
void prepare_reference_folder(const std::string& ref_dir, const std::string& new_dir);

// After run_compare(ref_dir, new_dir): writes the files the mode names,
// atomically, and the reference manifest with their new hashes.
UpdateResult update_reference(const CompareReport& report, const std::string& ref_dir,
                              const std::string& new_dir, UpdateMode mode);

}  // namespace facet
