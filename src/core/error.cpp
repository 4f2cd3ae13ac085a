#include "core/error.hpp"

namespace facet {

std::string SourceLocation::describe() const {
    if (!origin.empty()) return origin;
    if (file.empty()) return "<unknown>";
    if (line <= 0) return file;
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

static std::string compose(const SourceLocation& where, const std::string& key,
                           const std::string& message) {
    std::string text = where.describe() + ": ";
    if (!key.empty()) text += "'" + key + "': ";
    return text + message;
}

Error::Error(ExitCode code, const std::string& message)
    : std::runtime_error(message), code_(code) {}

Error::Error(ExitCode code, const SourceLocation& where, const std::string& key,
             const std::string& message)
    : std::runtime_error(compose(where, key, message)), code_(code) {}

void fail_input(const SourceLocation& where, const std::string& key, const std::string& message) {
    throw Error(ExitCode::invalid_input, where, key, message);
}

void fail_io(const std::string& path, const std::string& message) {
    throw Error(ExitCode::io_failure, path + ": " + message);
}

}  // namespace facet
