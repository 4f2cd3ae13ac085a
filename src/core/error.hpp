#pragma once
// Errors that carry an exit code and, where known, the place in a user's file
// that caused them. Every failure a user can cause ends as one of these.
#include <stdexcept>
#include <string>

namespace facet {

// The exit codes of shared/design.md §2.
enum class ExitCode : int {
    ok = 0,
    runtime_failure = 1,
    invalid_input = 2,  // usage error, invalid scene, style or asset
    comparison_failed = 3,
    io_failure = 4,
};

// A place in a text file, 1-based. line == 0 means "the whole file";
// an empty file with a non-empty `origin` means a command-line value.
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;
    std::string origin;  // e.g. "-D camera.fov=30" when the value came from the command line

    std::string describe() const;
};

class Error : public std::runtime_error {
  public:
    Error(ExitCode code, const std::string& message);
    Error(ExitCode code, const SourceLocation& where, const std::string& key,
          const std::string& message);

    ExitCode code() const { return code_; }

  private:
    ExitCode code_;
};

// Shorthands for the two most common kinds.
[[noreturn]] void fail_input(const SourceLocation& where, const std::string& key,
                             const std::string& message);
[[noreturn]] void fail_io(const std::string& path, const std::string& message);

}  // namespace facet
