#include "core/error.hpp"

#include "core/diagnostics.hpp"

namespace facet {

std::string SourceLocation::describe() const {
    if (!origin.empty()) return origin;
    if (file.empty()) return "<unknown>";
    if (line <= 0) return file;
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::string describe_problem(const SourceLocation& where, const std::string& key,
                             const std::string& message) {
    // Built by appending: GCC 12 at -O3 warns falsely (-Wrestrict, GCC bug
    // 105329) about some "literal" + std::string expressions.
    std::string text;
    if (!where.file.empty() || !where.origin.empty()) {
        text += where.describe();
        text += ": ";
    }
    if (!key.empty()) {
        text += '\'';
        text += key;
        text += "': ";
    }
    text += message;
    return text;
}

Error::Error(ExitCode code, const std::string& message)
    : std::runtime_error(message), code_(code), detail_(message) {}

Error::Error(ExitCode code, const SourceLocation& where, const std::string& key,
             const std::string& message)
    : std::runtime_error(describe_problem(where, key, message)),
      code_(code),
      where_(where),
      key_(key),
      detail_(message) {}

std::string Warning::describe() const {
    return describe_problem(where, key, message);
}

void fail_input(const SourceLocation& where, const std::string& key, const std::string& message) {
    throw Error(ExitCode::invalid_input, where, key, message);
}

void fail_io(const std::string& path, const std::string& message) {
    throw Error(ExitCode::io_failure, path + ": " + message);
}

}  // namespace facet
