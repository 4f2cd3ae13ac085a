#pragma once
// Render farm commands (docs/farm.md): the chunk options of render,
// `facet merge` and `facet farm slurm|openjd`.
#include <optional>
#include <string>
#include <vector>

#include "cli/render_args.hpp"
#include "farm/job_scripts.hpp"
#include "job/render_job.hpp"

namespace CLI {
class App;
}

namespace facet {

// render's --chunk, --chunk-from-env, --chunks, --chunk-frames, --skip-existing.
void add_chunk_options(CLI::App* command, ChunkArgs& args);

// The part of the job a render renders, or nullopt when no chunk option
// was given. `job_frames` are the job's (after --frames); `run_frames`
// receives the part's, which may be empty (more chunks than frames).
// Prints which chunk and why to stderr unless quiet: farm logs show it.
// A Slurm array task given no chunk option gets a warning in `warnings`.
std::optional<RunPart> choose_part(const ChunkArgs& args, const std::vector<int>& job_frames,
                                   std::vector<int>& run_frames, bool quiet, Warnings& warnings);

struct MergeArgs {
    std::string folder;
    bool keep_parts = false;
    bool quiet = false;
    std::vector<std::string> command_line;
};
CLI::App* add_merge_command(CLI::App& app, MergeArgs& args);
int merge_command(const MergeArgs& args);

struct FarmArgs {
    RenderArgs render;
    SlurmSettings slurm;
    OpenJobSettings openjd;
    std::string script;  // --script FILE; "" : standard output
};
// `facet farm slurm` and `facet farm openjd`; returns the farm command.
CLI::App* add_farm_command(CLI::App& app, FarmArgs& slurm, FarmArgs& openjd);
int farm_command(const FarmArgs& args, bool openjd);

}  // namespace facet
