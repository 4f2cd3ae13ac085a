#pragma once
// Errors that carry an exit code and, where known, the place in a user's file
// that caused them. Every failure a user can cause ends as one of these.
#include <stdexcept>
#include <string>

namespace facet {

// The exit codes (README, "Exit codes"; docs/architecture.md).
enum class ExitCode : int {
    ok = 0,
    runtime_failure = 1,
    invalid_input = 2,  // usage error, invalid scene, style or asset
    comparison_failed = 3,
    io_failure = 4,
    // Stopped by SIGINT or SIGTERM (Ctrl-C, a scheduler's time limit or
    // cancel) after writing what was done: rerun with --skip-existing.
    interrupted = 5,
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

// The one error type of the project: what() is the whole message a user
// reads ("file:line:col: 'key': detail"); the parts stay available for
// machine-readable reports (`validate --json`).
class Error : public std::runtime_error {
  public:
    Error(ExitCode code, const std::string& message);
    Error(ExitCode code, const SourceLocation& where, const std::string& key,
          const std::string& message);

    ExitCode code() const { return code_; }
    const SourceLocation& where() const { return where_; }  // empty when not known
    const std::string& key() const { return key_; }
    const std::string& detail() const { return detail_; }  // the message without place and key

  private:
    ExitCode code_;
    SourceLocation where_;
    std::string key_;
    std::string detail_;
};

// "file:line:col: 'key': message", or "'key': message" / "message" when
// the place is unknown.
std::string describe_problem(const SourceLocation& where, const std::string& key,
                             const std::string& message);

// Shorthands for the two most common kinds.
[[noreturn]] void fail_input(const SourceLocation& where, const std::string& key,
                             const std::string& message);
[[noreturn]] void fail_io(const std::string& path, const std::string& message);

}  // namespace facet
