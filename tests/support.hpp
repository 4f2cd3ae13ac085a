#pragma once
// Helpers shared by the test files: temporary folders, writing small files,
// and running the facet executable as a user would.
#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace facet::test {

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

struct RunResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Runs `facet ARGS` through the shell and captures what it prints.
inline RunResult run_facet(const std::string& args) {
    std::string command = std::string("'") + FACET_EXECUTABLE + "' " + args + " 2>&1";
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

inline std::string source_path(const std::string& relative) {
    return (std::filesystem::path(FACET_SOURCE_DIR) / relative).string();
}

}  // namespace facet::test
