#pragma once
// The thresholds file of `facet compare --thresholds FILE`
// (docs/regression.md, "Thresholds file"): YAML read into the compare
// module's plain records, every value checked with file, line and column.
#include <string>

#include "compare/thresholds.hpp"

namespace facet {

// Starts from default_thresholds() and applies the file. Errors are
// facet::Error(invalid_input) naming file, line, column and key.
CompareThresholds load_thresholds_file(const std::string& path);

}  // namespace facet
