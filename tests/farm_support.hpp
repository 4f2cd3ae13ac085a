#pragma once
// Helpers for the render farm tests: a small animated scene, and reading
// what a run's manifest lists.
#include <sys/stat.h>

#include <map>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "compare_support.hpp"
#include "support.hpp"

namespace facet::test {

// A scene of `frames` frames whose images differ from frame to frame.
inline std::string write_farm_scene(const TempDir& dir, int frames, const std::string& size) {
    return write_text(dir.file("spin.yaml"), R"(
output: { size: )" + size + R"(, frames: "1-)" + std::to_string(frames) +
                                                 R"(", passes: [color, depth], formats: [png, exr] }
camera: { orbit: { radius: 4, turns: 1 } }
lights: [ { type: directional, direction: [-1, -1, -1] } ]
objects: [ { primitive: { type: torus }, material: { color: [0.8, 0.4, 0.2] } } ]
)");
}

inline std::string sha256_of_file(const std::string& path) {
    const std::string bytes = read_file(path);
    return sha256_hex(bytes.data(), bytes.size());
}

// path -> sha256, as a manifest lists its files.
inline std::map<std::string, std::string> listed_hashes(const std::string& manifest) {
    std::map<std::string, std::string> hashes;
    const nlohmann::json listed = read_json(manifest);  // alive through the loop
    for (const auto& f : listed["files"])
        hashes[f["path"].get<std::string>()] = f["sha256"].get<std::string>();
    return hashes;
}

inline size_t count_substring(const std::string& text, const std::string& needle) {
    size_t count = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
        ++count;
    return count;
}

// Names in `folder` that start with '.' and are not the manifest lock:
// temporaries and journals.
inline std::vector<std::string> hidden_leftovers(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (name[0] == '.' && name != ".facet-manifest.lock") names.push_back(name);
    }
    return names;
}

// A folder with the farm scene, and stubs on PATH: `sbatch` records its
// arguments, one per line, and answers a job id; `facet` records its own.
struct FarmFolder {
    TempDir dir{"farm-injection"};
    std::string scene = write_farm_scene(dir, 4, "[32, 18]");

    FarmFolder() {
        std::filesystem::create_directories(dir.file("bin"));
        for (const char* stub : {"sbatch", "scontrol", "facet-stub"}) {
            const std::string path = dir.file(std::string("bin/") + stub);
            write_text(path, std::string("#!/bin/bash\nprintf '%s\\n' \"$@\" >> ") +
                                 shell_quote(dir.file(std::string(stub) + ".args")) +
                                 "\necho 4242\n");
            ::chmod(path.c_str(), 0755);
        }
    }
    // `facet farm slurm` in the folder, with `options` (already quoted).
    RunResult farm(const std::string& options) const {
        return run_in(dir.path(), " farm slurm spin.yaml --chunks 2 --script job.sh " + options);
    }
    // `facet ARGS` (already quoted) run in `folder`.
    RunResult run_in(const std::string& folder, const std::string& args) const {
        return run_command("cd " + shell_quote(folder) + " && " + shell_quote(facet_executable()) +
                           " " + args + " 2>&1");
    }
    // The script run as a user runs it, or as a task with FACET_FARM_STEP.
    RunResult run_script(const std::string& env = "", const std::string& script = "job.sh") const {
        return run_command("cd " + shell_quote(dir.path()) +
                           " && PATH=" + shell_quote(dir.file("bin")) + ":\"$PATH\" " + env +
                           " bash " + shell_quote(script) + " 2>&1");
    }
    std::vector<std::string> recorded(const std::string& stub) const {
        std::vector<std::string> lines;
        std::istringstream in(read_file(dir.file(stub + ".args")));
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        return lines;
    }
    bool pwned() const { return std::filesystem::exists(dir.file("PWNED")); }
};

}  // namespace facet::test
