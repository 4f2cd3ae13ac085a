#pragma once
// Warnings: problems that do not stop a run (a key without effect, a mesh
// part that is skipped). Every module reports them the same way, with the
// place they come from, so the command line prints them, and `--json`
// lists them, alike. Errors are facet::Error (core/error.hpp).
#include <string>
#include <vector>

#include "core/error.hpp"

namespace facet {

struct Warning {
    SourceLocation where;  // file (and line) it comes from; empty when unknown
    std::string key;       // the scene key or the asset's element, if any
    std::string message;

    // "file:line:col: 'key': message", as errors read.
    std::string describe() const;
};

using Warnings = std::vector<Warning>;

// A warning about a whole file (an asset), without a line.
inline Warning file_warning(const std::string& file, const std::string& message) {
    Warning w;
    w.where.file = file;
    w.message = message;
    return w;
}

}  // namespace facet
