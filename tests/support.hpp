#pragma once
// Helpers shared by the test files: temporary folders, reading and writing
// small files, expecting facet::Error, and running the facet executable as a
// user would.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace facet::test {

// Where things are (test_paths.cpp).
std::string source_dir();        // the checkout
std::string baselines_dir();     // tests/baselines: the reviewed reference images
std::string facet_executable();  // the facet program just built
std::string build_dir();
std::string styles_dir();      // the shipped presets
std::string override_scene();  // the scene the -D fuzz harness overrides

// A fresh folder under the system temp dir, removed when the object dies.
class TempDir {
  public:
    explicit TempDir(const std::string& tag) {
        std::string base =
            (std::filesystem::temp_directory_path() / ("facet-test-" + tag + "-XXXXXX")).string();
        path_ = ::mkdtemp(base.data()) ? base : std::string();
    }
    ~TempDir() {
        std::error_code ec;
        if (!path_.empty()) std::filesystem::remove_all(path_, ec);
    }
    const std::string& path() const { return path_; }
    std::string file(const std::string& name) const {
        return (std::filesystem::path(path_) / name).string();
    }

  private:
    std::string path_;
};

inline std::string write_text(const std::string& path, const std::string& text) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

inline std::string write_bytes(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    return path;
}

// The whole file as it is on disk (empty if it cannot be read).
inline std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs `run` and requires a facet::Error with exit code `code` whose message
// contains `needle` (normally the file name). Any other exception escapes and
// fails the test.
template <typename F>
void require_error(F&& run, facet::ExitCode code, const std::string& needle) {
    try {
        run();
        FAIL("expected facet::Error mentioning '" << needle << "'");
    } catch (const facet::Error& e) {
        CHECK(e.code() == code);
        CHECK_THAT(e.what(), Catch::Contains(needle));
    }
}

template <typename F>
void require_input_error(F&& run, const std::string& needle) {
    require_error(run, facet::ExitCode::invalid_input, needle);
}

struct RunResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Runs a shell command and captures what it prints on stdout.
inline RunResult run_command(const std::string& command) {
    RunResult result;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    int status = ::pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// Runs `facet ARGS` through the shell and captures what it prints.
inline RunResult run_facet(const std::string& args) {
    return run_command(std::string("'") + facet::test::facet_executable() + "' " + args + " 2>&1");
}

// Whether this build (and so the facet it runs) has AddressSanitizer.
using facet::kAddressSanitizer;

// Runs `facet ARGS` as run_facet does, but killed after `seconds` of wall
// time (a blocked read uses no CPU) and limited to `megabytes` of address
// space, so that a regression towards a hang or a runaway allocation fails
// the test instead of stalling the suite or the machine. Sanitizer builds
// reserve terabytes of address space up front, so there only time counts.
inline RunResult run_facet_limited(const std::string& args, int seconds, int megabytes) {
    std::string limits =
        kAddressSanitizer ? "" : "ulimit -v " + std::to_string(megabytes * 1024) + "; ";
    std::string command = "sh -c \"" + limits + "exec timeout -s KILL " + std::to_string(seconds) +
                          " '" + facet::test::facet_executable() + "' " + args + " 2>&1\"";
    return run_command(command);
}

// A test whose tool or data is missing: it says why and stops. Under ctest
// (which sets FACET_TEST_SKIP_CODE, tests/CMakeLists.txt) the process ends
// with that code, which ctest counts as skipped, never passed; run by hand,
// the reason is a warning and the test returns.
#define FACET_SKIP(reason)                                               \
    do {                                                                 \
        const std::string skip_reason_ = (reason);                       \
        if (const char* code_ = std::getenv("FACET_TEST_SKIP_CODE")) {   \
            std::fprintf(stderr, "skipped: %s\n", skip_reason_.c_str()); \
            std::fflush(nullptr);                                        \
            std::_Exit(std::atoi(code_));                                \
        }                                                                \
        WARN("skipped: " << skip_reason_);                               \
        return;                                                          \
    } while (0)

// Whether a command is on the PATH.
inline bool have_command(const std::string& name) {
    return run_command("command -v '" + name + "' >/dev/null 2>&1").exit_code == 0;
}

inline std::string source_path(const std::string& relative) {
    return (std::filesystem::path(facet::test::source_dir()) / relative).string();
}

}  // namespace facet::test
